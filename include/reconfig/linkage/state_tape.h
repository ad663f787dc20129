#pragma once
/// @file
/// The local derivatives of every reconstruction step, recorded during a solve, for
/// reverse-mode (adjoint) gradients: ∂f/∂x̄ of a scalar f(x) in O(#rules) per configuration,
/// instead of forming all of ∂x/∂x̄ (StateDerivatives).

#include <Eigen/Core>
#include <vector>

namespace reconfig::linkage {

class StateTape {
 public:
  /// Chain rule in reverse: given G = ∂f/∂x (2×#J), adds ∂f/∂x̄ = Σ_k (∂x_k/∂x̄)ᵀ G.col(k)
  /// to `out` (2×#J). Same result as StateDerivatives::pull_back.
  void pull_back(const Eigen::Matrix2Xd& G, Eigen::Matrix2Xd& out) const;

  /// One recorded rule (i, j) → k: x_k depends on x_i, x_j (Mi, Mj) and directly on
  /// x̄_i, x̄_j, x̄_k (Pi, Pj, Pk). i, j are −1 when absent. For a Newton block, `block`
  /// indexes `blocks` instead.
  struct Step {
    int k = -1, i = -1, j = -1, block = -1;
    // Zero, not left uninitialized (Eigen's default): a step is reset with `step = {}`.
    Eigen::Matrix2d Mi = Eigen::Matrix2d::Zero(), Mj = Eigen::Matrix2d::Zero(), Pi = Eigen::Matrix2d::Zero(),
                    Pj = Eigen::Matrix2d::Zero(), Pk = Eigen::Matrix2d::Zero();
  };
  /// A Newton block: outputs y (its joints), known inputs z, parameters x̄ of `params`;
  /// dy = S_in dz + S_param dx̄ (implicit function theorem).
  struct Block {
    std::vector<int> outputs, inputs, params;
    Eigen::MatrixXd S_in, S_param;
  };
  std::vector<Step> steps;  ///< in rule order
  std::vector<Block> blocks;

 private:
  mutable Eigen::Matrix2Xd adjoint_;
};

}  // namespace reconfig::linkage
