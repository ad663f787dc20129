#pragma once
/// @file
/// The screw motion that interpolates two rigid poses (Rossignac & Kim, "Animating and
/// sweeping polyhedra along interpolating screw motions").

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace reconfig::motion {

/// The minimal-angle screw motion from rigid map A (t = 0) to rigid map B (t = 1):
/// `M(t) = D^t ∘ A`, where D = B A⁻¹ is the relative rigid map, written as a rotation by the
/// angle b ∈ [0, π] about the axis line through `point()` with unit direction `axis()`
/// (right-handed), combined with a translation by d along that axis; D^t turns by t·b and
/// slides by t·d. Every point moves on a helix about the axis at constant speed.
///
/// Properties (tested): M(0) = A, M(1) = B; independent of the world and body frames
/// (G A H, G B H give G M(t) H); inserting M(t') as a key pose leaves the motion unchanged.
///
/// Numerical care: D^t is evaluated without going through `point()` — its translation is
/// `t d s + Rot_s((t−1) b/2) · (sin(t b/2)/sin(b/2)) · o⊥` with o⊥ the part of D's
/// translation orthogonal to s — so angles down to 1e-12 (where the axis point is ~1e12
/// away) and exactly 0 are continuous and accurate.
///
/// Degenerate cases, decided deterministically:
/// - b = 0 (pure translation by o, or identity): `axis()` = o/|o| (or +z when o = 0),
///   `distance()` = |o|, `point()` = origin.
/// - b = π (the relative quaternion's scalar part is below 1e-12 in magnitude): both turning
///   directions are minimal. The angle is taken to be exactly π, and the axis sign is
///   chosen so that its component of largest magnitude is positive (the lowest index wins
///   a tie). Such a screw is not coordinate-free (the tie-break looks at world axes) and
///   reproduces B only to ~1e-12 relative accuracy.
class ScrewMotion {
 public:
  /// The motion that stays at the identity.
  ScrewMotion();

  /// @param A  rigid map at t = 0 (its linear part must be a rotation)
  /// @param B  rigid map at t = 1 (its linear part must be a rotation)
  ScrewMotion(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B);

  /// M(t) = D^t A. Any real t is accepted (t outside [0, 1] continues the screw).
  Eigen::Isometry3d at(double t) const;

  /// D^t: the part of the screw done by time t, as a rigid map of space.
  Eigen::Isometry3d relative_at(double t) const;

  /// Rotation part of D^t as a unit quaternion (turn by t·b about axis()).
  Eigen::Quaterniond relative_rotation(double t) const;

  const Eigen::Isometry3d& start() const { return A_; }  ///< A
  const Eigen::Isometry3d& end() const { return B_; }    ///< B
  const Eigen::Vector3d& axis() const { return s_; }     ///< unit s
  /// The point of the axis closest to the world origin (the origin itself when b = 0).
  const Eigen::Vector3d& point() const { return p_; }
  double angle() const { return b_; }     ///< b ∈ [0, π], radians
  double distance() const { return d_; }  ///< d, signed slide along axis()
  bool is_translation() const { return b_ == 0.0; }
  /// o⊥: the part of D's translation orthogonal to the axis; its length is the chord of the
  /// arc that the world origin's projection travels, 2 ρ sin(b/2) (ρ: distance to axis).
  const Eigen::Vector3d& perpendicular_translation() const { return o_perp_; }

 private:
  Eigen::Isometry3d A_, B_;
  Eigen::Vector3d s_, p_, o_perp_;
  double b_ = 0.0, d_ = 0.0;
};

}  // namespace reconfig::motion
