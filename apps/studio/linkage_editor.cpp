#include "linkage_editor.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "reconfig/common/input_error.h"
#include "reconfig/linkage/curve_edit.h"
#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/linkage_motion.h"

namespace reconfig::studio {
namespace {

using namespace reconfig::linkage;

double degrees(double radians) { return radians * 180 / std::numbers::pi; }

double orientation(const Eigen::Matrix2Xd& X, const Rule& rule) {
  const Eigen::Vector2d a = X.col(rule.j) - X.col(rule.i), b = X.col(rule.k) - X.col(rule.i);
  return a.x() * b.y() - a.y() * b.x();
}

std::string range_problem(const MotionRange& range) {
  if (range.full_rotation) return "";
  return fmt::format("crank cannot turn fully: range [{:.1f}°, {:.1f}°]", degrees(range.lower), degrees(range.upper));
}

}  // namespace

std::vector<Eigen::Vector2d> resample_curve(const std::vector<Eigen::Vector2d>& curve, const std::vector<double>& from,
                                            const std::vector<double>& to, bool periodic) {
  const int n = static_cast<int>(from.size());
  if (n < 2 || curve.size() != from.size()) return curve;
  std::vector<Eigen::Vector2d> result;
  for (double angle : to) {
    double u;  // fractional index into `from`
    if (periodic) {
      const double step = 2 * std::numbers::pi / n;
      u = std::fmod(std::fmod((angle - from.front()) / step, n) + n, n);
    } else {
      const auto above = std::upper_bound(from.begin(), from.end(), angle);
      const int i = std::clamp(static_cast<int>(above - from.begin()) - 1, 0, n - 2);
      u = i + std::clamp((angle - from[i]) / (from[i + 1] - from[i]), 0.0, 1.0);
    }
    const int i = std::min(static_cast<int>(u), n - 1), j = periodic ? (i + 1) % n : std::min(i + 1, n - 1);
    result.push_back((1 - (u - i)) * curve[i] + (u - i) * curve[j]);
  }
  return result;
}

std::vector<int> flipped_triangles(const JointOrder& order, const Eigen::Matrix2Xd& before,
                                   const Eigen::Matrix2Xd& after) {
  std::vector<int> flipped;
  for (const Rule& rule : order.rules)
    if (rule.kind == RuleKind::kTriangle && !(orientation(before, rule) * orientation(after, rule) > 0))
      flipped.push_back(rule.k);
  return flipped;
}

void LinkageEditor::set_linkage(Linkage linkage) {
  auto kinematics = std::make_unique<SymbolicKinematics>(linkage, order_joints(linkage));
  const MotionRange range = motion_range(*kinematics);
  std::vector<double> angles = edit_sample_angles(linkage, kSamples);
  std::vector<std::vector<Eigen::Vector2d>> curves;
  for (const TrackingPoint& point : linkage.tracking_points) curves.push_back(joint_trajectory(linkage, point.joint, angles));
  const std::size_t points = linkage.tracking_points.size();
  if (keep.size() != points || targets.size() != points) {
    keep.assign(points, false);
    targets.assign(points, std::nullopt);
  }
  for (auto& target : targets)
    if (target) *target = resample_curve(*target, angles_, angles, range.full_rotation);
  linkage_ = std::move(linkage);
  kinematics_ = std::move(kinematics);
  range_ = range;
  angles_ = std::move(angles);
  curves_ = std::move(curves);
}

void LinkageEditor::reset_choices() {
  keep.assign(linkage_.tracking_points.size(), false);
  targets.assign(linkage_.tracking_points.size(), std::nullopt);
  enclosure.reset();
}

std::string LinkageEditor::motion_problem() const {
  std::string problem = range_problem(range_);
  if (motor_interval) {
    const std::string interval = motor_interval_error(range_, motor_interval->first, motor_interval->second);
    if (!interval.empty()) problem += (problem.empty() ? "" : "; ") + interval;
  }
  return problem;
}

int LinkageEditor::dead_point_joint() const {
  if (range_.full_rotation) return -1;
  return range_.upper_failure.joint >= 0 ? range_.upper_failure.joint : range_.lower_failure.joint;
}

bool LinkageEditor::solve(double angle, Eigen::Matrix2Xd& X) const {
  return kinematics_ && kinematics_->solve(angle, X);
}

void LinkageEditor::drag_target(int point, int index, const Eigen::Vector2d& displacement, double radius) {
  const auto& base = targets[point] ? *targets[point] : curves_[point];
  targets[point] = soft_drag_curve(base, index, displacement, radius, range_.full_rotation);
}

void LinkageEditor::transform_target(int point, double scale, double rotation, const Eigen::Vector2d& translation) {
  const auto& base = targets[point] ? *targets[point] : curves_[point];
  targets[point] = transform_curve(base, scale, rotation, translation);
}

EditObjectives LinkageEditor::objectives() const {
  EditObjectives objectives;
  for (std::size_t p = 0; p < linkage_.tracking_points.size(); ++p) {
    const int joint = linkage_.tracking_points[p].joint;
    if (targets[p]) objectives.trajectories.push_back({joint, *targets[p], kTrajectoryWeight});
    else if (keep[p]) objectives.trajectories.push_back({joint, curves_[p], kTrajectoryWeight});
  }
  if (enclosure) objectives.envelope = EditObjectives::Envelope{enclosure->first, enclosure->second, kEnvelopeWeight};
  return objectives;
}

LinkageEditOutcome LinkageEditor::drag_joint(int joint, const Eigen::Vector2d& target, double angle) const {
  EditObjectives goals = objectives();
  const bool initial = std::abs(std::remainder(angle - initial_angle(), 2 * std::numbers::pi)) < 1e-9;
  goals.drags.push_back({joint, target, initial ? std::nullopt : std::optional(angle), 1.0});
  LinkageEditOutcome outcome = run(goals);
  if (!outcome.refusal.empty()) return outcome;
  const auto position = [&](const Linkage& which) -> Eigen::Vector2d {
    if (initial) return which.joints[joint].position;
    Eigen::Matrix2Xd X;
    SymbolicKinematics(which, order_joints(which)).solve(angle, X);
    return X.col(joint);
  };
  const double before = (position(linkage_) - target).norm(), after = (position(outcome.result.linkage) - target).norm();
  if (!(after < before))
    outcome.refusal = fmt::format("cannot move {} toward ({:.3g}, {:.3g}) without breaking the linkage ({})",
                                  linkage_.joints[joint].name, target.x(), target.y(), outcome.result.status);
  outcome.summary = fmt::format("{} to ({:.4g}, {:.4g}): {:.3g} -> {:.3g} from the target", linkage_.joints[joint].name,
                                target.x(), target.y(), before, after) +
                    outcome.summary;
  return outcome;
}

LinkageEditOutcome LinkageEditor::fit() const { return run(objectives()); }

LinkageEditOutcome LinkageEditor::run(const EditObjectives& objectives) const {
  LinkageEditOutcome outcome;
  if (empty()) {
    outcome.refusal = "no linkage is open";
    return outcome;
  }
  if (objectives.drags.empty() && objectives.trajectories.empty() && !objectives.envelope) {
    outcome.refusal = "nothing to edit: drag a joint, set a target curve or an enclosure";
    return outcome;
  }
  EditSettings settings;
  settings.samples = kSamples;
  try {
    outcome.result = edit_linkage(linkage_, objectives, settings);
  } catch (const std::exception& error) {
    outcome.refusal = fmt::format("the edit failed: {}", error.what());
    return outcome;
  }
  if (outcome.result.linkage.initial_positions() == linkage_.initial_positions()) {
    outcome.refusal = fmt::format("every step of that edit would break the linkage ({})", outcome.result.status);
    return outcome;
  }
  outcome.refusal = refusal(outcome.result.linkage);
  for (const auto& trajectory : objectives.trajectories) {
    double worst = 0;
    const auto after = joint_trajectory(outcome.result.linkage, trajectory.joint, angles_);
    for (std::size_t s = 0; s < after.size(); ++s) worst = std::max(worst, (after[s] - trajectory.curve[s]).norm());
    outcome.summary += fmt::format("; {} within {:.3g} of its curve", linkage_.joints[trajectory.joint].name, worst);
  }
  if (outcome.summary.starts_with("; ")) outcome.summary.erase(0, 2);
  return outcome;
}

std::string LinkageEditor::refusal(const Linkage& edited) const {
  const std::vector<int> flipped =
      flipped_triangles(kinematics_->order(), linkage_.initial_positions(), edited.initial_positions());
  if (!flipped.empty())
    return fmt::format("joint {} would flip to the other branch of its triangle", linkage_.joints[flipped[0]].name);
  try {
    check_linkage(edited);
    const MotionRange after = motion_range(SymbolicKinematics(edited, order_joints(edited)));
    if (range_.full_rotation && !after.full_rotation) return "the edit would stop the crank: " + range_problem(after);
    if (motor_interval) return motor_interval_error(after, motor_interval->first, motor_interval->second);
  } catch (const InputError& error) {
    return fmt::format("the edit would break the linkage: {}", error.what());
  }
  return "";
}

double LinkageEditor::deviation(const Linkage& linkage, int point, const std::vector<double>& angles,
                                const std::vector<Eigen::Vector2d>& curve) {
  try {
    const auto after = joint_trajectory(linkage, linkage.tracking_points[point].joint, angles);
    double worst = 0;
    for (std::size_t s = 0; s < after.size() && s < curve.size(); ++s) worst = std::max(worst, (after[s] - curve[s]).norm());
    return worst;
  } catch (const InputError&) {
    return std::numeric_limits<double>::infinity();
  }
}

}  // namespace reconfig::studio
