#include "scene/detail/rotation_json.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

namespace reconfig::scene::detail {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

Eigen::Quaterniond read_axis_angle(const JsonCursor& c) {
  c.expect_object({"axis", "degrees"});
  const JsonCursor axis = c["axis"];
  const Eigen::Vector3d direction = axis.as_vector3();
  const double length = direction.norm();
  if (!(length > 0) || !std::isfinite(length)) axis.fail("the axis must be a nonzero, finite direction");
  return Eigen::Quaterniond(Eigen::AngleAxisd(radians(c["degrees"].as_number()), direction / length));
}

/// `order` names the fixed axis of each angle, first rotation first: "xyz" turns about x, then
/// about the unmoved y, then about the unmoved z (R = R_z R_y R_x).
Eigen::Quaterniond read_euler(const JsonCursor& c) {
  c.expect_object({"euler_degrees", "order"});
  const JsonCursor order = c["order"];
  const std::string axes = order.as_string();
  const bool valid = axes.size() == 3 && axes.find_first_not_of("xyz") == std::string::npos && axes[0] != axes[1] &&
                     axes[1] != axes[2];
  if (!valid) order.fail(fmt::format("expected three of x, y, z with no axis twice in a row (\"xyz\", \"zxz\"), found \"{}\"", axes));
  const Eigen::Vector3d degrees = c["euler_degrees"].as_vector3();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(axes[static_cast<std::size_t>(i)] - 'x');
    q = Eigen::Quaterniond(Eigen::AngleAxisd(radians(degrees[i]), axis)) * q;
  }
  return q.normalized();
}

}  // namespace

Eigen::Quaterniond read_rotation(const JsonCursor& c) {
  if (c.value().is_array()) return c.as_unit_quaternion();
  if (!c.value().is_object())
    c.fail(fmt::format("expected a quaternion [w, x, y, z], {{\"axis\", \"degrees\"}} or {{\"euler_degrees\", \"order\"}}, "
                       "found {}", c.value().type_name()));
  if (c.has("euler_degrees") || c.has("order")) return read_euler(c);
  return read_axis_angle(c);
}

}  // namespace reconfig::scene::detail
