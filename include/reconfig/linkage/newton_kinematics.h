#pragma once
/// @file
/// The numerical baseline LinkEdit compares against: every link is a rigid body with a
/// pose (x, y, θ), joints are pin constraints between bodies (and to the ground for fixed
/// joints), the motor fixes the crank's angle; Newton's method (Gauss–Newton on the sparse
/// constraint Jacobian) solves the constraints, warm-started from the previous solution.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "reconfig/linkage/linkage.h"

namespace reconfig::linkage {

class NewtonKinematics {
 public:
  explicit NewtonKinematics(const Linkage& linkage);

  /// Solves for motor value `angle` (radians) starting from the last solution (or the
  /// initial configuration). @param X output joint positions, 2×#J
  /// @param iterations if not null, the Newton iterations used
  /// @return false if Newton did not converge (|constraint| ≤ 1e-12 · size) in 50 iterations
  bool solve(double angle, Eigen::Matrix2Xd& X, int* iterations = nullptr);

  /// Back to the initial configuration.
  void reset();

  int unknowns() const { return static_cast<int>(state_.size()); }
  int equations() const { return equations_; }

 private:
  void residual(double angle, Eigen::VectorXd& r, Eigen::SparseMatrix<double>* J) const;
  Eigen::Vector2d world(int link, int slot) const;

  struct Pin {
    int link_a = -1, slot_a = -1;  // joint on body a
    int link_b = -1, slot_b = -1;  // joint on body b, or -1: ground at `ground`
    Eigen::Vector2d ground = Eigen::Vector2d::Zero();
  };
  Linkage linkage_;
  std::vector<std::vector<Eigen::Vector2d>> local_;  // per link, per carried joint: rest offset
  std::vector<Pin> pins_;
  std::vector<std::pair<int, int>> joint_slot_;  // per joint: (link, slot) that places it, or (-1, -1)
  int crank_ = -1;
  double angle0_ = 0;
  int equations_ = 0;
  double scale_ = 1;
  Eigen::VectorXd state_;  // 3 per link: x, y, θ
};

}  // namespace reconfig::linkage
