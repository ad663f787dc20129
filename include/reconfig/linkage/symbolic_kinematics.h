#pragma once
/// @file
/// Symbolic (closed-form) reconstruction of a linkage's joint positions from the motor
/// value (LinkEdit eq. 1–2), and the state derivatives ∂x/∂x̄ by recursion over the rules.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/linkage.h"
#include "reconfig/linkage/state_derivatives.h"
#include "reconfig/linkage/state_tape.h"

namespace reconfig::linkage {

/// Why a reconstruction failed.
struct ReconstructionFailure {
  enum class Kind {
    kNone,
    kCannotClose,   ///< a reconstruction triangle violates the triangle inequality
    kNewtonFailed,  ///< a complex loop's Newton solve did not converge or went singular
  };
  Kind kind = Kind::kNone;
  int rule = -1;   ///< index into JointOrder::rules
  int joint = -1;  ///< the joint that could not be placed
  std::string message;
};

/// The closed-form kinematics of one linkage: the rule order plus the constants (lengths,
/// triangle orientations, rigid coordinates) of an initial configuration.
///
/// Not thread-safe when the order has Newton blocks (they keep their last solution as the
/// next starting guess and are continued in steps of at most 3° from the last angle to the
/// new one, unwrapped: pass angles that reach the target the way round you mean);
/// otherwise `solve` is a pure function and may run concurrently.
class SymbolicKinematics {
 public:
  /// @throws reconfig::InputError (without a file) if a reconstruction triangle is
  ///         degenerate (collinear) in the initial configuration, naming the joint
  SymbolicKinematics(const Linkage& linkage, JointOrder order);

  const Linkage& linkage() const { return linkage_; }
  const JointOrder& order() const { return order_; }
  int joint_count() const { return static_cast<int>(linkage_.joints.size()); }

  /// Replaces the initial configuration (editing) and recomputes the constants; the rule
  /// order is kept. @param X0 2×#J
  /// @return false (and keeps the old configuration) if a reconstruction triangle is
  ///         degenerate in X0
  bool set_initial_positions(const Eigen::Matrix2Xd& X0);
  const Eigen::Matrix2Xd& initial_positions() const { return X0_; }

  /// Motor value of the initial configuration (radians).
  double initial_angle() const { return angle0_; }

  /// Joint positions at motor value `angle` (radians).
  /// @param X        output, 2×#J (resized)
  /// @param failure  if not null, filled when the result is false
  /// @return false if some joint cannot be reconstructed (X then holds garbage past it)
  bool solve(double angle, Eigen::Matrix2Xd& X, ReconstructionFailure* failure = nullptr) const;

  /// Joint positions and their derivatives with respect to the initial positions x̄,
  /// at fixed motor value. @param D output, resized on first use and reused after
  bool solve(double angle, Eigen::Matrix2Xd& X, StateDerivatives& D, ReconstructionFailure* failure = nullptr) const;

  /// Joint positions, recording the local derivatives of every rule for reverse-mode
  /// gradients (StateTape::pull_back), the fast way to ∂f/∂x̄ of a scalar objective.
  bool solve(double angle, Eigen::Matrix2Xd& X, StateTape& tape, ReconstructionFailure* failure = nullptr) const;

  /// Newton blocks only: forget the last solution and continue from the initial
  /// configuration again (call before jumping to an angle on the other side of a dead point).
  void reset_continuation() const;

  /// Eq. (6) for every triangle rule: d_s = 1 − cos²α (α: angle at the reconstructed
  /// joint) at positions X. @return one value per triangle rule, in rule order
  std::vector<double> singularity_distances(const Eigen::Matrix2Xd& X) const;

  /// Indices (into order().rules) of the triangle rules, the order singularity_distances uses.
  const std::vector<int>& triangle_rules() const { return triangle_rules_; }

 private:
  struct Constants;
  bool compute_constants(const Eigen::Matrix2Xd& X0, std::vector<Constants>& constants, std::string* error,
                         int* joint) const;
  bool solve_continued(double angle, Eigen::Matrix2Xd& X, StateDerivatives* D, StateTape* tape,
                       ReconstructionFailure* failure) const;
  bool solve_once(double angle, Eigen::Matrix2Xd& X, StateDerivatives* D, StateTape* tape,
                  ReconstructionFailure* failure) const;
  bool solve_block(int rule_index, Eigen::Matrix2Xd& X, StateDerivatives* D, StateTape* tape,
                   ReconstructionFailure* failure) const;
  void build_dependencies();

  Linkage linkage_;
  JointOrder order_;
  Eigen::Matrix2Xd X0_;
  double angle0_ = 0;
  std::vector<int> triangle_rules_;

  struct Constants {
    double A = 0, B = 0;  // kTriangle: squared lengths l_ik², l_jk²; kMotor: A = radius
    double sign = 1;      // kTriangle: orientation of (i, j, k) in x̄
    Eigen::Vector2d e_ik = Eigen::Vector2d::Zero(), e_jk = Eigen::Vector2d::Zero();  // x̄_k − x̄_i, x̄_k − x̄_j
    double a = 0, b = 0;  // kRigid
    Eigen::Vector2d da_di, da_dj, da_dk, db_di, db_dj, db_dk;  // kRigid gradients
  };
  std::vector<Constants> constants_;

  // Derivative bookkeeping: for rule r, where the dependencies of its inputs and its direct
  // parameters land in the dependency list of its output.
  struct RuleMaps {
    std::vector<int> from_i, from_j;  // positions in deps(k) of deps(i)[m], deps(j)[m]
    int pos_i = -1, pos_j = -1, pos_k = -1;
  };
  std::vector<RuleMaps> maps_;
  StateDerivatives layout_;  // dependency lists, zero blocks

  // Newton blocks: last solution (guess) per block and the angle it was found at.
  mutable std::vector<Eigen::Matrix2Xd> block_guess_;
  mutable double guess_angle_ = 0;
};

}  // namespace reconfig::linkage
