#include "axis_angle.h"

#include <cmath>
#include <numbers>

namespace reconfig::studio {

AxisAngle axis_angle_of(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd turn(q.normalized());  // angle in [0, π]
  AxisAngle result;
  result.degrees = turn.angle() * 180 / std::numbers::pi;
  if (turn.angle() > 0) result.axis = turn.axis();
  return result;
}

std::optional<Eigen::Quaterniond> rotation_of(const AxisAngle& rotation) {
  const double length = rotation.axis.norm();
  if (!(length > 0) || !std::isfinite(length) || !std::isfinite(rotation.degrees)) return std::nullopt;
  return Eigen::Quaterniond(Eigen::AngleAxisd(rotation.degrees * std::numbers::pi / 180, rotation.axis / length));
}

}  // namespace reconfig::studio
