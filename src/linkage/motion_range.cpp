#include "reconfig/linkage/motion_range.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace reconfig::linkage {
namespace {

std::string degrees(double radians) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f°", radians * 180 / std::numbers::pi);
  return buffer;
}

// Walks from the initial angle in direction `sign` until a reconstruction fails or a whole
// turn is done; returns the last good angle (refined) and the failure beyond it.
bool walk(const SymbolicKinematics& kinematics, double sign, double step, double& end, ReconstructionFailure& failure) {
  const double start = kinematics.initial_angle();
  Eigen::Matrix2Xd X;
  kinematics.reset_continuation();
  const int steps = static_cast<int>(std::ceil(2 * std::numbers::pi / step));
  double good = start;
  for (int s = 1; s <= steps; ++s) {
    const double angle = start + sign * std::min(s * step, 2 * std::numbers::pi);
    if (kinematics.solve(angle, X, &failure)) {
      good = angle;
      continue;
    }
    double bad = angle;
    kinematics.solve(good, X);
    while (std::abs(bad - good) > 1e-12) {
      const double middle = 0.5 * (good + bad);
      ReconstructionFailure trial;
      if (kinematics.solve(middle, X, &trial)) {
        good = middle;
      } else {
        bad = middle;
        failure = trial;
        kinematics.solve(good, X);
      }
    }
    end = good;
    // Just beyond a dead point the failing triangle is degenerate: name it that way.
    const Rule& rule = kinematics.order().rules[failure.rule];
    if (failure.kind == ReconstructionFailure::Kind::kCannotClose)
      failure.message = "triangle " + describe_rule(kinematics.linkage(), kinematics.order(), rule) +
                        " flattens (a dead point) and cannot close beyond";
    else {
      std::string names;
      for (int k : kinematics.order().blocks[rule.block].joints)
        names += (names.empty() ? "\"" : ", \"") + kinematics.linkage().joints[k].name + "\"";
      failure.message = "complex loop {" + names + "} locks (a dead point)";
    }
    kinematics.reset_continuation();
    return false;
  }
  end = good;
  kinematics.reset_continuation();
  return true;
}

}  // namespace

bool MotionRange::contains(double angle) const {
  if (full_rotation) return true;
  const double turn = 2 * std::numbers::pi;
  const double shifted = lower + std::fmod(std::fmod(angle - lower, turn) + turn, turn);
  return shifted <= upper + 1e-12;
}

std::string MotionRange::describe() const {
  if (full_rotation) return "full rotation";
  std::string text = "rocks between " + degrees(lower) + " and " + degrees(upper);
  if (lower_failure.message == upper_failure.message) return text + " (at both ends: " + upper_failure.message + ")";
  return text + " (at " + degrees(lower) + ": " + lower_failure.message + "; at " + degrees(upper) + ": " +
         upper_failure.message + ")";
}

MotionRange motion_range(const SymbolicKinematics& kinematics, double step) {
  MotionRange range;
  const double start = kinematics.initial_angle();
  if (walk(kinematics, +1, step, range.upper, range.upper_failure)) {
    range.full_rotation = true;
    range.lower = start;
    range.upper = start + 2 * std::numbers::pi;
    return range;
  }
  walk(kinematics, -1, step, range.lower, range.lower_failure);
  return range;
}

}  // namespace reconfig::linkage
