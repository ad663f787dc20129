#include "reconfig/collision/kdop.h"

namespace reconfig::collision {
namespace {

/// Every nonzero direction with components in {−1, 0, 1} whose first nonzero component is +1
/// (one per ± pair), over the first `dims` coordinates; the remaining ones are 0.
template <std::size_t N>
std::array<Eigen::Vector4d, N> sign_directions(int dims, bool add_time_axis) {
  std::array<Eigen::Vector4d, N> axes;
  std::size_t n = 0;
  int total = 1;
  for (int d = 0; d < dims; ++d) total *= 3;
  // Order: unit axes first, then the rest in counting order (stable and readable).
  for (int d = 0; d < dims; ++d) {
    Eigen::Vector4d v = Eigen::Vector4d::Zero();
    v[d] = 1;
    axes[n++] = v;
  }
  for (int code = 0; code < total && n + (add_time_axis ? 1 : 0) < N; ++code) {
    Eigen::Vector4d v = Eigen::Vector4d::Zero();
    int c = code, nonzero = 0, first = 0;
    for (int d = 0; d < dims; ++d, c /= 3) {
      v[d] = (c % 3) - 1;
      if (v[d] != 0 && nonzero++ == 0) first = static_cast<int>(v[d]);
    }
    if (nonzero < 2 || first != 1) continue;
    axes[n++] = v;
  }
  if (add_time_axis) axes[n++] = Eigen::Vector4d(0, 0, 0, 1);
  return axes;
}

}  // namespace

template <>
const std::array<Eigen::Vector4d, 4>& dop_axes<DopFamily::k8>() {
  static const auto axes = sign_directions<4>(3, true);  // x, y, z, t
  return axes;
}

template <>
const std::array<Eigen::Vector4d, 14>& dop_axes<DopFamily::k28>() {
  static const auto axes = sign_directions<14>(3, true);
  return axes;
}

template <>
const std::array<Eigen::Vector4d, 40>& dop_axes<DopFamily::k80>() {
  static const auto axes = sign_directions<40>(4, false);
  return axes;
}

}  // namespace reconfig::collision
