#pragma once
/// @file
/// What the linkage panel edits (LinkEdit §4–§5), without any UI: one planar linkage, its
/// motion range and tracking-point curves, and the edits the panel offers — drag a joint, fit
/// tracking points to target curves, fit into an enclosure box — each run by the library's
/// function-preserving optimization (linkage_edit.h) and checked before it is offered: an edit
/// that cannot move the linkage, flips a reconstruction triangle to the other branch, or
/// leaves a motion the motor interval does not fit is refused with the reason.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reconfig/linkage/linkage.h"
#include "reconfig/linkage/linkage_edit.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::studio {

/// The result of one edit request: the edited linkage, or why it is refused.
struct LinkageEditOutcome {
  linkage::EditResult result;
  std::string refusal;  ///< empty: the edit may be applied
  std::string summary;  ///< what it did, for the status line ("U moved 7.1 toward …")
};

/// `curve` sampled at motor angles `from` (radians, ascending; evenly over a turn when
/// `periodic`) resampled at `to` by linear interpolation in the angle (clamped at the ends when
/// not periodic): a target curve kept through an edit that moves the sample angles.
std::vector<Eigen::Vector2d> resample_curve(const std::vector<Eigen::Vector2d>& curve, const std::vector<double>& from,
                                            const std::vector<double>& to, bool periodic);

/// The triangle rules of `order` whose orientation (sign of the triangle (i, j, k)) differs
/// between the initial configurations `before` and `after` (2×#J each): the joints that would
/// be reconstructed on the other branch. @return the reconstructed joints k, in rule order
std::vector<int> flipped_triangles(const linkage::JointOrder& order, const Eigen::Matrix2Xd& before,
                                   const Eigen::Matrix2Xd& after);

class LinkageEditor {
 public:
  /// Sample angles of edits and kept/target curves (LinkEdit's default, as `reconfig linkage edit`).
  static constexpr int kSamples = 72;
  /// Weights as `reconfig linkage edit` uses them: a drag 1, a trajectory and the enclosure 10.
  static constexpr double kTrajectoryWeight = 10, kEnvelopeWeight = 10;

  /// Starts editing `linkage` (already checked: linkage_file.h's check_linkage). The keep
  /// flags and targets stay when it has as many tracking points (after an edit), else they
  /// are cleared; `reset_choices` clears them and the enclosure (another linkage).
  /// @throws InputError if its kinematics cannot be set up
  void set_linkage(linkage::Linkage linkage);
  void reset_choices();
  bool empty() const { return !kinematics_; }
  const linkage::Linkage& linkage() const { return linkage_; }
  const linkage::MotionRange& range() const { return range_; }
  /// The motor interval the linkage must keep working over (radians, unwrapped), e.g. a
  /// transition's drive; none: only "a crank that turned fully still does".
  std::optional<std::pair<double, double>> motor_interval;

  /// What is wrong with the motion, or "": "crank cannot turn fully: range [a°, b°]" when the
  /// crank only rocks, and the motor interval's problem (linkage_motion.h) if it does not fit.
  std::string motion_problem() const;
  /// The joint that stops the motion at a dead point (−1 for a full rotation).
  int dead_point_joint() const;

  /// Joint positions at motor angle `angle` (radians). @return false past a dead point
  bool solve(double angle, Eigen::Matrix2Xd& X) const;
  double initial_angle() const { return kinematics_ ? kinematics_->initial_angle() : 0.0; }
  /// The angles the edits sample (edit_sample_angles) and tracking point p's positions there.
  const std::vector<double>& sample_angles() const { return angles_; }
  const std::vector<Eigen::Vector2d>& curve(int point) const { return curves_[point]; }

  /// Per tracking point: keep its curve in every edit (the panel's checkboxes).
  std::vector<bool> keep;
  /// Per tracking point: the curve it should follow (one point per sample angle), if set;
  /// set_linkage resamples it at the new sample angles.
  std::vector<std::optional<std::vector<Eigen::Vector2d>>> targets;
  /// Keep every joint inside this box over the motion, in every edit.
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> enclosure;

  /// The target of tracking point `point` (or its curve) soft-dragged (curve_edit.h): sample
  /// `index` moves by `displacement`, its neighbours along the curve less, within `radius`.
  void drag_target(int point, int index, const Eigen::Vector2d& displacement, double radius);
  /// The target (or curve) of `point` scaled, rotated (radians) about its centroid and moved.
  void transform_target(int point, double scale, double rotation, const Eigen::Vector2d& translation);

  /// LinkEdit with joint `joint` pulled to `target`, in the configuration at motor angle
  /// `angle` (radians; the initial one when it is the initial angle), with the kept curves,
  /// the targets and the enclosure.
  LinkageEditOutcome drag_joint(int joint, const Eigen::Vector2d& target, double angle) const;
  /// LinkEdit towards the targets and into the enclosure (nothing dragged).
  LinkageEditOutcome fit() const;
  /// The largest distance of tracking point `point`'s motion in `linkage` at motor angles
  /// `angles` (radians) from `curve` (one point per angle); +∞ if the linkage breaks there.
  static double deviation(const linkage::Linkage& linkage, int point, const std::vector<double>& angles,
                          const std::vector<Eigen::Vector2d>& curve);

 private:
  linkage::EditObjectives objectives() const;
  LinkageEditOutcome run(const linkage::EditObjectives& objectives) const;
  /// Why `edited` may not replace the linkage, or "".
  std::string refusal(const linkage::Linkage& edited) const;

  linkage::Linkage linkage_;
  std::unique_ptr<linkage::SymbolicKinematics> kinematics_;
  linkage::MotionRange range_;
  std::vector<double> angles_;
  std::vector<std::vector<Eigen::Vector2d>> curves_;
};

}  // namespace reconfig::studio
