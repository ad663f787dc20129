#pragma once
/// @file
/// Discrete oriented polytopes in 4D spacetime (x, y, z, t) (reconfigurables §5.1).

#include <Eigen/Core>
#include <array>
#include <limits>
#include <optional>

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

/// The family with `halfspaces` halfspaces (8, 28 or 80), or none for another number.
constexpr std::optional<DopFamily> dop_family(int halfspaces) {
  if (halfspaces == 8) return DopFamily::k8;
  if (halfspaces == 28) return DopFamily::k28;
  if (halfspaces == 80) return DopFamily::k80;
  return std::nullopt;
}

/// The axes of a family as 4D directions (spatial part, temporal part), not normalized.
/// Axis i of `Kdop<family>` measures `direction(i) · (x, y, z, t)`.
template <DopFamily family>
const std::array<Eigen::Vector4d, axis_count(family)>& dop_axes();

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
    const auto& axes = dop_axes<family>();
    for (int i = 0; i < kAxes; ++i) {
      const double v = axes[i].template head<3>().dot(p) + axes[i][3] * t;
      lo[i] = std::min(lo[i], v);
      hi[i] = std::max(hi[i], v);
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
