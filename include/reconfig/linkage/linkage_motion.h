#pragma once
/// @file
/// The 3D adapter: a planar linkage, its plane placed in 3D, moves rigid bodies attached to
/// its links as the motor turns from one angle to another — as exact rigid maps, and compiled
/// into piecewise screw motions (motion::ScrewKey) that stay within a tolerance of them.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"
#include "reconfig/motion/screw_track.h"

namespace reconfig::linkage {

/// Where the linkage plane sits in 3D: the plane point (x, y) (linkage units) is at
/// `pose * (scale·x, scale·y, 0)` (3D units). The plane normal is `pose.linear() * +z`.
struct PlanePlacement {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double scale = 1.0;  ///< 3D units per linkage unit, > 0
};

/// A rigid body carried by a link. The link frame has its origin at joint `origin`, its x axis
/// toward joint `toward` (two joints of one link), and its z axis along the plane normal;
/// `offset` maps the body's rest points into that frame (3D units, not scaled).
struct LinkAttachment {
  int origin = -1;  ///< index into Linkage::joints
  int toward = -1;  ///< index into Linkage::joints, on a link with `origin`
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
};

/// The link frame as a rigid map of 3D space (link-frame point ↦ world point).
/// @param X  2×#J joint positions
Eigen::Isometry3d link_frame(const Eigen::Matrix2Xd& X, int origin, int toward, const PlanePlacement& plane);

/// Rest point p of the attached body is at `attached_map(...) * p`:
/// `link_frame(X, a.origin, a.toward, plane) * a.offset`.
Eigen::Isometry3d attached_map(const Eigen::Matrix2Xd& X, const LinkAttachment& attachment,
                               const PlanePlacement& plane);

/// Whether `origin` and `toward` are two distinct joints carried by one link.
bool share_a_link(const Linkage& linkage, int origin, int toward);

/// An empty string if the motor can turn from `from` to `to` (radians, unwrapped: 0 → 2π is
/// one counterclockwise turn) without leaving `range`; otherwise what goes wrong, e.g.
/// "the motor cannot turn from 0.0° to 120.0°: the linkage rocks between −82.8° and 82.8° (…)".
/// For a rocking linkage one shift of both angles by a whole number of turns is allowed.
std::string motor_interval_error(const MotionRange& range, double from, double to);

/// How far apart two placements of a body put its points: a bound, over every point p with
/// |p − center| ≤ radius, of |A p − B p| — namely |A c − B c| + radius · 2 sin(φ/2), φ the
/// angle of the rotation between them (exact for the worst point when the bound is attained).
double placement_distance(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B, const Eigen::Vector3d& center,
                          double radius);

/// A body to move: where it is attached and the ball (about `center`, its pose pivot) that
/// holds its points, which sets how closely the compiled motion must follow.
struct AttachedBody {
  LinkAttachment attachment;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

/// The true motion: over time t ∈ [0, 1] the motor angle runs linearly from `from` to `to`.
class LinkageMotion {
 public:
  /// @param kinematics  must outlive this object
  /// @param from, to    motor angles in radians (unwrapped)
  LinkageMotion(const SymbolicKinematics& kinematics, PlanePlacement plane, double from, double to);

  double angle_at(double t) const { return from_ + t * (to_ - from_); }
  const PlanePlacement& plane() const { return plane_; }

  /// Joint positions at time t. @return false if the linkage cannot be reconstructed there
  bool joints_at(double t, Eigen::Matrix2Xd& X, ReconstructionFailure* failure = nullptr) const;

  /// The rigid maps of `bodies` at time t (rest point ↦ world point).
  /// @throws reconfig::InputError (without file, location "motor") if the linkage breaks at t,
  ///         (location "") if a map is not finite (a placement too large for doubles)
  std::vector<Eigen::Isometry3d> maps_at(double t, const std::vector<AttachedBody>& bodies) const;

 private:
  const SymbolicKinematics& kinematics_;
  PlanePlacement plane_;
  double from_, to_;
};

/// What to compile and how closely.
struct CompileMotionRequest {
  std::vector<AttachedBody> bodies;
  /// Largest distance any point of a body may be from where the linkage puts it (3D units).
  /// Keys are added until, at `checks_per_segment` evenly spaced times inside every segment,
  /// the measured distance is at most tolerance / 2 (the other half is a margin for the
  /// unsampled times in between; tests measure densely that the whole tolerance holds).
  double tolerance = 1e-4;
  int checks_per_segment = 16;
  /// Initial segments: one per `initial_step` radians of motor turn (at least one).
  double initial_step = 10.0 * 3.14159265358979323846 / 180.0;
  /// Shortest segment (in t) refinement may produce; needing a shorter one is an error.
  double min_segment = 1e-7;
  /// Most key times the motion may take; more is an error (a tolerance far too small for the
  /// size of the bodies, or a motor turning thousands of times).
  int max_keys = 20000;
};

/// Key poses for each body on common key times 0 = t_0 < ... < t_n = 1.
struct CompiledMotion {
  std::vector<double> times;
  /// keys[b][k]: body b at times[k], as a pose about bodies[b].center (eq. 9), quaternion
  /// normalized.
  std::vector<std::vector<motion::ScrewKey>> keys;
  /// The largest distance measured at the check times between the screw interpolation of the
  /// keys and the true motion (≤ tolerance / 2).
  double deviation = 0.0;
};

/// Samples the true motion adaptively (deterministic bisection of segments) into screw keys.
/// @throws reconfig::InputError without a file, its location naming the request field to
///         blame: "motor" if the linkage breaks on the way, "tolerance" if more than
///         `max_keys` keys or a segment shorter than `min_segment` would be needed, "" if a
///         placement is not finite
CompiledMotion compile_motion(const LinkageMotion& motion, const CompileMotionRequest& request);

}  // namespace reconfig::linkage
