#pragma once
/// @file
/// Discrete oriented polytopes in 4D spacetime (x, y, z, t) (reconfigurables §5.1).

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>
#include <utility>

#include "reconfig/scene/collision_settings.h"

namespace reconfig::collision {

/// The families of axes a spacetime k-DOP can use.
enum class DopFamily {
  k8,   ///< the 4D axis-aligned box: x, y, z, t
  k28,  ///< the 26 spatial halfspaces of the cube's faces, edges and corners, plus t (default)
  k80,  ///< every direction with components in {−1, 0, 1}⁴: mixed space–time axes too
};

/// Number of axes (half the number of halfspaces) of a family.
constexpr int axis_count(DopFamily family) {
  return family == DopFamily::k8 ? 4 : family == DopFamily::k28 ? 14 : 40;
}

/// The number of halfspaces of a family (8, 28 or 80: how `--dop` and the papers name it).
constexpr int halfspace_count(DopFamily family) { return 2 * axis_count(family); }

/// Every family, by their number of halfspaces: those of `scene::kDopHalfspaces`, the one list
/// of the counts a scene file or `--dop` may name.
inline constexpr std::array<DopFamily, 3> kDopFamilies = {DopFamily::k8, DopFamily::k28, DopFamily::k80};
static_assert([] {
  for (std::size_t i = 0; i < kDopFamilies.size(); ++i)
    if (halfspace_count(kDopFamilies[i]) != scene::kDopHalfspaces[i]) return false;
  return kDopFamilies.size() == scene::kDopHalfspaces.size();
}());

/// The family with `halfspaces` halfspaces (8, 28 or 80), or none for another number.
constexpr std::optional<DopFamily> dop_family(int halfspaces) {
  for (const DopFamily family : kDopFamilies)
    if (halfspace_count(family) == halfspaces) return family;
  return std::nullopt;
}

/// Calls `f.template operator()<family>()` with `family` known at compile time, and returns
/// what it returns: the one place a family chosen at run time becomes a template argument.
template <class F>
decltype(auto) with_dop_family(DopFamily family, F&& f) {
  if (family == DopFamily::k8) return f.template operator()<DopFamily::k8>();
  if (family == DopFamily::k28) return f.template operator()<DopFamily::k28>();
  return f.template operator()<DopFamily::k80>();
}

/// The axes of a family as 4D directions with components in {−1, 0, 1}: the unit axes of the
/// family's `dims` coordinates first, then every other such direction whose first nonzero
/// component is +1 (one per ± pair), in counting order (base 3, first coordinate fastest); the
/// 8- and 28-DOP add the time axis last.
template <DopFamily family>
constexpr std::array<std::array<int, 4>, axis_count(family)> dop_axis_signs() {
  constexpr int kDims = family == DopFamily::k80 ? 4 : 3;
  constexpr bool kTimeAxis = family != DopFamily::k80;
  constexpr int kCount = axis_count(family);
  std::array<std::array<int, 4>, kCount> axes{};
  int n = 0;
  for (int d = 0; d < kDims; ++d) axes[n++][d] = 1;
  int total = 1;
  for (int d = 0; d < kDims; ++d) total *= 3;
  for (int code = 0; code < total && n + (kTimeAxis ? 1 : 0) < kCount; ++code) {
    std::array<int, 4> v{};
    int c = code, nonzero = 0, first = 0;
    for (int d = 0; d < kDims; ++d, c /= 3) {
      v[d] = c % 3 - 1;
      if (v[d] != 0 && nonzero++ == 0) first = v[d];
    }
    if (nonzero >= 2 && first == 1) axes[n++] = v;
  }
  if (kTimeAxis) axes[n++] = {0, 0, 0, 1};
  return axes;
}

/// The axes of a family as 4D directions (spatial part, temporal part), not normalized
/// (`dop_axis_signs`). Axis i of `Kdop<family>` measures `direction(i) · (x, y, z, t)`.
template <DopFamily family>
const std::array<Eigen::Vector4d, axis_count(family)>& dop_axes();

namespace dop_detail {
/// s₀x + s₁y + s₂z + s₃t for signs in {−1, 0, 1} known at compile time: additions only.
template <int s0, int s1, int s2, int s3>
inline double signed_sum(double x, double y, double z, double t) {
  constexpr int kSigns[4] = {s0, s1, s2, s3};
  const double values[4] = {x, y, z, t};
  double sum = 0;
  bool started = false;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (
        [&] {
          if constexpr (kSigns[I] != 0) {
            const double term = kSigns[I] > 0 ? values[I] : -values[I];
            sum = started ? sum + term : term;
            started = true;
          }
        }(),
        ...);
  }(std::make_index_sequence<4>());
  return sum;
}
}  // namespace dop_detail

/// The values of the spacetime point (p, t) along every axis of a family, with additions
/// only (the axes' components are −1, 0 or 1).
template <DopFamily family>
inline Eigen::Matrix<double, axis_count(family), 1> axis_values(const Eigen::Vector3d& p, double t) {
  constexpr auto kSigns = dop_axis_signs<family>();
  Eigen::Matrix<double, axis_count(family), 1> out;
  [&]<std::size_t... J>(std::index_sequence<J...>) {
    ((out[J] = dop_detail::signed_sum<kSigns[J][0], kSigns[J][1], kSigns[J][2], kSigns[J][3]>(p.x(), p.y(), p.z(), t)), ...);
  }(std::make_index_sequence<axis_count(family)>());
  return out;
}

/// A k-DOP: for each axis the interval [lo, hi] of `axis · point` over the bounded set.
/// Default-constructed it is empty (lo = +∞, hi = −∞).
template <DopFamily family>
struct Kdop {
  static constexpr int kAxes = axis_count(family);
  std::array<double, kAxes> lo, hi;

  Kdop() {
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
  }

  bool empty() const { return lo[0] > hi[0]; }

  /// Whether the two closed k-DOPs overlap on every axis (a conservative overlap test).
  bool overlaps(const Kdop& other) const {
    for (int i = 0; i < kAxes; ++i)
      if (lo[i] > other.hi[i] || other.lo[i] > hi[i]) return false;
    return true;
  }

  /// Grows the k-DOP to contain the spacetime point (p, t).
  void extend(const Eigen::Vector3d& p, double t) {
    const auto values = axis_values<family>(p, t);
    for (int i = 0; i < kAxes; ++i) {
      lo[i] = std::min(lo[i], values[i]);
      hi[i] = std::max(hi[i], values[i]);
    }
  }

  /// Grows the k-DOP to contain another.
  void extend(const Kdop& other) {
    for (int i = 0; i < kAxes; ++i) {
      lo[i] = std::min(lo[i], other.lo[i]);
      hi[i] = std::max(hi[i], other.hi[i]);
    }
  }

  /// Grows every spatial extent by `distance` (the Minkowski sum with a ball of that radius
  /// in space): axis i widens by distance × |spatial part of axis i|.
  void inflate(double distance) {
    const auto& axes = dop_axes<family>();
    for (int i = 0; i < kAxes; ++i) {
      const double pad = distance * axes[i].template head<3>().norm();
      lo[i] -= pad;
      hi[i] += pad;
    }
  }
};

}  // namespace reconfig::collision
