#pragma once
/// @file
/// A part's motion seen from another part's frame: f_A⁻¹ ∘ f_B (reconfigurables §6.7, eq. 4).

#include <Eigen/Geometry>

#include <functional>
#include <string>
#include <vector>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::sweep {

/// The rigid motion g(t), t ∈ [t0, t1], that carries the rest-pose points of a moving part B
/// into the rest frame of a reference part A (or into world space when there is no A), with a
/// conservative bound on how far any point of B moves under it.
class RelativeMotion {
 public:
  /// (t) ↦ g(t): rest point p of B goes to g(t) · p in A's frame.
  using PoseFunction = std::function<Eigen::Isometry3d(double t)>;
  /// (a, b) ↦ D with |g(t)p − g(a)p| <= D for every t ∈ [a, b] and every point p of B (any
  /// point within the radius the bound was built for).
  using DisplacementBound = std::function<double(double a, double b)>;

  /// @param pose          g(t)
  /// @param displacement  the bound above, for t0 <= a <= b <= t1
  /// @param t0, t1        the time range, t0 <= t1
  RelativeMotion(PoseFunction pose, DisplacementBound displacement, double t0, double t1);

  Eigen::Isometry3d at(double t) const { return pose_(t); }
  double displacement_bound(double a, double b) const { return displacement_(a, b); }
  double start_time() const { return t0_; }
  double end_time() const { return t1_; }

  /// Times t0 = τ_0 < … < τ_m = t1 such that no point of B moves more than `tolerance`
  /// over any [τ_k, τ_{k+1}]: each step from τ_k as long as `displacement_bound` allows (found
  /// by bisection on its length), never shorter than `min_step` (and then the bound reached
  /// is reported).
  /// @param tolerance  > 0
  /// @param reached    out: the largest bound over the steps (may exceed `tolerance` only
  ///                   when a step hit `min_step`)
  std::vector<double> time_samples(double tolerance, double& reached, double min_step = 1e-7) const;

 private:
  PoseFunction pose_;
  DisplacementBound displacement_;
  double t0_ = 0, t1_ = 1;
};

/// The motion of part `part` during `transition` over [t0, t1], seen from part `relative_to`
/// (−1: world space). Derivation of the bound: with w(t) = M_B(t)p and q(t) = M_A(t)⁻¹w(t),
/// |q(t) − q(a)| <= |w(t) − w(a)| + |M_A(t)y − M_A(a)y| where y = q(a): B's own displacement
/// bound (radius r_B about its center) plus A's displacement bound for the radius
/// |c_B(a) − c_A(a)| + r_B about A's center (c(a): the world centers at a). Both come from
/// `motion/motion_bounds.h`.
/// @param scene        a validated reconfigurable; it must outlive the returned motion
/// @param transition   index into scene.transitions
/// @param part         B, index into scene.parts
/// @param relative_to  A, index into scene.parts, or −1
/// @param t0, t1       0 <= t0 <= t1 <= 1
RelativeMotion relative_motion(const scene::Reconfigurable& scene, int transition, int part, int relative_to,
                               double t0 = 0.0, double t1 = 1.0);

}  // namespace reconfig::sweep
