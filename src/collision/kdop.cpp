#include "reconfig/collision/kdop.h"

namespace reconfig::collision {
namespace {

template <DopFamily family>
std::array<Eigen::Vector4d, axis_count(family)> axes_of() {
  std::array<Eigen::Vector4d, axis_count(family)> axes;
  const auto signs = dop_axis_signs<family>();
  for (std::size_t i = 0; i < axes.size(); ++i) axes[i] = Eigen::Vector4d(signs[i][0], signs[i][1], signs[i][2], signs[i][3]);
  return axes;
}

}  // namespace

template <>
const std::array<Eigen::Vector4d, 4>& dop_axes<DopFamily::k8>() {
  static const auto axes = axes_of<DopFamily::k8>();  // x, y, z, t
  return axes;
}

template <>
const std::array<Eigen::Vector4d, 14>& dop_axes<DopFamily::k28>() {
  static const auto axes = axes_of<DopFamily::k28>();
  return axes;
}

template <>
const std::array<Eigen::Vector4d, 40>& dop_axes<DopFamily::k80>() {
  static const auto axes = axes_of<DopFamily::k80>();
  return axes;
}

}  // namespace reconfig::collision
