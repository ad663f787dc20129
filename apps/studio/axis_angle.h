#pragma once
/// @file
/// A rotation as the inspector shows and edits it: an angle about an axis, as a person thinks
/// of a door turning about its hinge. Unlike Euler angles it does not jump while a part turns
/// about one axis (a door turned ~61° read `180, 180, 118.94`): the axis stays and the angle
/// grows.

#include <Eigen/Geometry>
#include <optional>

namespace reconfig::studio {

struct AxisAngle {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< unit length
  double degrees = 0;                               ///< in [0, 180]
};

/// The axis and angle of `q`; the identity reads 0° about +z.
AxisAngle axis_angle_of(const Eigen::Quaterniond& q);

/// The rotation by `degrees` about `axis` (any nonzero length), or nothing for a zero or
/// non-finite axis or angle.
std::optional<Eigen::Quaterniond> rotation_of(const AxisAngle& rotation);

}  // namespace reconfig::studio
