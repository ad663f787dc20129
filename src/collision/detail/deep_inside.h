#pragma once
/// @file
/// Whether a part lies inside another when their surfaces do not interfere: decided by one of
/// its vertices deeper than the contact tolerance δ inside the other, or outside it by more
/// than δ. A vertex within δ of the other's surface (a part resting on or in another) cannot
/// decide, so the next one that can does.

#include <Eigen/Core>
#include <optional>

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/mesh.h"
#include "reconfig/geometry/point_in_solid.h"

namespace reconfig::collision::detail {

/// Whether q lies within `delta` of the surface of `mesh` (brute force).
inline bool near_surface(const geometry::Mesh& mesh, const Eigen::Vector3d& q, double delta) {
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    if ((geometry::closest_point_on_triangle(q, a, b, c).point - q).squaredNorm() <= delta * delta) return true;
  }
  return false;
}

/// Whether `probe` decides: inside `outer` (true), outside (false), or within δ of its surface
/// (nothing).
inline std::optional<bool> deep_side(const geometry::Mesh& outer, const Eigen::Vector3d& probe, double delta) {
  if (near_surface(outer, probe, delta)) return std::nullopt;
  return geometry::point_in_solid(outer, probe);
}

/// Whether the part whose posed vertices are the rows of `inner` lies inside `outer`, their
/// surfaces not interfering: vertex `probe` decides, or if it lies within δ of `outer`'s
/// surface, the first vertex that does not (none: not inside).
inline bool lies_inside(const geometry::Mesh& outer, const Eigen::MatrixX3d& inner, Eigen::Index probe, double delta) {
  if (const auto side = deep_side(outer, inner.row(probe).transpose(), delta)) return *side;
  for (Eigen::Index v = 0; v < inner.rows(); ++v)
    if (const auto side = deep_side(outer, inner.row(v).transpose(), delta)) return *side;
  return false;
}

}  // namespace reconfig::collision::detail
