#include "geometry/detail/triangulate_polygon.h"

#include <Eigen/Geometry>
#include <cmath>

namespace reconfig::geometry::detail {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

void fan(const std::vector<int>& loop, std::size_t begin, std::vector<Eigen::Vector3i>& triangles) {
  for (std::size_t i = begin + 1; i + 1 < loop.size(); ++i) triangles.emplace_back(loop[begin], loop[i], loop[i + 1]);
}

}  // namespace

void triangulate_polygon(const std::vector<Eigen::Vector3d>& positions, const std::vector<int>& loop,
                         std::vector<Eigen::Vector3i>& triangles) {
  const std::size_t n = loop.size();
  if (n < 3) return;
  if (n == 3 || n > 1000) return fan(loop, 0, triangles);
  auto at = [&](std::size_t i) -> const Eigen::Vector3d& { return positions[static_cast<std::size_t>(loop[i])]; };
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // Newell's method
  for (std::size_t i = 0; i < n; ++i) normal += at(i).cross(at((i + 1) % n));
  if (!(normal.squaredNorm() > 0) || !normal.allFinite()) return fan(loop, 0, triangles);
  // Project onto the plane perpendicular to the normal's largest axis, counter-clockwise.
  int axis;
  normal.cwiseAbs().maxCoeff(&axis);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double flip = normal[axis] > 0 ? 1.0 : -1.0;
  std::vector<Eigen::Vector2d> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = Eigen::Vector2d(at(i)[u], flip * at(i)[v]);

  std::vector<std::size_t> remaining(n);
  for (std::size_t i = 0; i < n; ++i) remaining[i] = i;
  while (remaining.size() > 3) {
    const std::size_t m = remaining.size();
    bool clipped = false;
    for (std::size_t k = 0; k < m && !clipped; ++k) {
      const std::size_t a = remaining[(k + m - 1) % m], b = remaining[k], c = remaining[(k + 1) % m];
      if (cross2(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat corner
      bool empty = true;
      for (std::size_t j = 0; j < m && empty; ++j) {
        const std::size_t q = remaining[j];
        if (q == a || q == b || q == c) continue;
        empty = !(cross2(p[a], p[b], p[q]) >= 0 && cross2(p[b], p[c], p[q]) >= 0 && cross2(p[c], p[a], p[q]) >= 0);
      }
      if (!empty) continue;
      triangles.emplace_back(loop[a], loop[b], loop[c]);
      remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) {  // self-overlapping or degenerate: fan what is left
      std::vector<int> rest;
      for (std::size_t i : remaining) rest.push_back(loop[i]);
      return fan(rest, 0, triangles);
    }
  }
  triangles.emplace_back(loop[remaining[0]], loop[remaining[1]], loop[remaining[2]]);
}

}  // namespace reconfig::geometry::detail
