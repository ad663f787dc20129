#pragma once
/// @file
/// The state derivatives ∂x/∂x̄ of a linkage: how each current joint position moves when
/// initial joint positions move, stored sparsely (a joint depends only on its ancestors).

#include <Eigen/Core>
#include <vector>

namespace reconfig::linkage {

/// ∂x_k/∂x̄_p as 2×2 blocks, for every joint k and each joint p it depends on.
class StateDerivatives {
 public:
  /// Sets the sparsity: deps[k] lists (sorted) the joints whose initial position x_k
  /// depends on. All blocks become zero.
  void set_layout(const std::vector<std::vector<int>>& deps);

  int joint_count() const { return static_cast<int>(deps_.size()); }
  const std::vector<int>& dependencies(int k) const { return deps_[k]; }
  /// ∂x_k/∂x̄_p for p = dependencies(k)[m].
  Eigen::Matrix2d& block(int k, int m) { return blocks_[offset_[k] + m]; }
  const Eigen::Matrix2d& block(int k, int m) const { return blocks_[offset_[k] + m]; }
  /// All blocks of joint k (dependencies(k).size() of them).
  Eigen::Matrix2d* blocks(int k) { return blocks_.data() + offset_[k]; }
  const Eigen::Matrix2d* blocks(int k) const { return blocks_.data() + offset_[k]; }

  /// The dense matrix: 2#J × 2#J, entry (2k + r, 2p + c) = ∂x_k[r]/∂x̄_p[c].
  Eigen::MatrixXd dense() const;

  /// Chain rule for a scalar f(x): given G = ∂f/∂x (2×#J, column k = ∂f/∂x_k), returns
  /// ∂f/∂x̄ (2×#J) = Σ_k (∂x_k/∂x̄)ᵀ G.col(k), added to `out`.
  void pull_back(const Eigen::Matrix2Xd& G, Eigen::Matrix2Xd& out) const;

 private:
  std::vector<std::vector<int>> deps_;
  std::vector<int> offset_;
  std::vector<Eigen::Matrix2d> blocks_;
};

}  // namespace reconfig::linkage
