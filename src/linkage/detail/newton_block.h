#pragma once
// Equations of a Newton block (complex kinematic loop): link rigidity written over joint
// positions, with the constants (squared lengths, rigid coordinates a, b) taken from the
// initial configuration. Shared by the ordering (rank check) and the kinematics.

#include <Eigen/Dense>
#include <vector>

#include "reconfig/linkage/joint_order.h"

namespace reconfig::linkage::detail {

/// Rigid coordinates of k in the frame of (i, j) in the initial configuration:
/// x̄_k − x̄_i = a d̄ + b ⟂d̄ with d̄ = x̄_j − x̄_i and ⟂(x, y) = (−y, x).
struct RigidCoordinates {
  double a = 0, b = 0;
  // Gradients of a and b with respect to x̄_i, x̄_j, x̄_k.
  Eigen::Vector2d da_di, da_dj, da_dk, db_di, db_dj, db_dk;
};
RigidCoordinates rigid_coordinates(const Eigen::Vector2d& xi, const Eigen::Vector2d& xj, const Eigen::Vector2d& xk);

inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
inline double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }
/// The matrix of ⟂: perp(v) = kPerp * v.
inline Eigen::Matrix2d perp_matrix() { return (Eigen::Matrix2d() << 0, -1, 1, 0).finished(); }

/// A block's equations ready to evaluate: the joints they involve (block joints first) and
/// the constants from the initial configuration.
class BlockSystem {
 public:
  BlockSystem(const NewtonBlock& block, const Eigen::Matrix2Xd& X0);

  /// Joints involved: the block's unknowns first (in block order), then known joints.
  const std::vector<int>& involved() const { return involved_; }
  int unknowns() const { return 2 * static_cast<int>(block_->joints.size()); }
  int equations() const { return equations_; }

  /// Residual at positions X (2×#J). @param J  if not null: #eq × 2·#involved derivative
  /// with respect to the positions of the involved joints.
  void evaluate(const Eigen::Matrix2Xd& X, Eigen::VectorXd& r, Eigen::MatrixXd* J) const;

  /// #eq × 2·#involved derivative of the residual with respect to the initial positions x̄
  /// of the involved joints, at current positions X.
  Eigen::MatrixXd parameter_jacobian(const Eigen::Matrix2Xd& X) const;

 private:
  int column(int joint) const;
  const NewtonBlock* block_;
  std::vector<int> involved_;
  int equations_ = 0;
  std::vector<double> length2_;                        // per link equation set
  std::vector<std::vector<RigidCoordinates>> rigid_;  // per link, per other joint
  std::vector<Eigen::Vector2d> d0_;                    // per link: x̄_r1 − x̄_r0
};

}  // namespace reconfig::linkage::detail
