#pragma once
/// @file
/// Helpers shared by the exact-kernel tests (triangle intersection, BVH, winding number,
/// self-intersections): a minimal OFF reader independent of the mesh loaders under test,
/// and small geometric references.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "support/test_data.h"

namespace reconfig::testing {

/// Reads a (triangle or polygon) OFF file; polygons are fanned into triangles.
inline geometry::Mesh read_off_for_test(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string header;
  in >> header;
  if (header != "OFF") throw std::runtime_error("not an OFF file: " + path.string());
  int nv = 0, nf = 0, ne = 0;
  in >> nv >> nf >> ne;
  geometry::Mesh mesh;
  mesh.V.resize(nv, 3);
  for (int i = 0; i < nv; ++i) in >> mesh.V(i, 0) >> mesh.V(i, 1) >> mesh.V(i, 2);
  std::vector<Eigen::Vector3i> tris;
  for (int f = 0; f < nf; ++f) {
    int k = 0;
    in >> k;
    std::vector<int> poly(k);
    for (int& v : poly) in >> v;
    std::string rest;
    std::getline(in, rest);  // optional colors
    for (int i = 1; i + 1 < k; ++i) tris.emplace_back(poly[0], poly[i], poly[i + 1]);
  }
  if (!in) throw std::runtime_error("truncated OFF file: " + path.string());
  mesh.F.resize(static_cast<int>(tris.size()), 3);
  for (int f = 0; f < static_cast<int>(tris.size()); ++f) mesh.F.row(f) = tris[f].transpose();
  return mesh;
}

inline geometry::Mesh cgal_off(const std::string& name) { return read_off_for_test(cgal_mesh(name)); }

/// Distance from p to segment [a, b] (a == b allowed).
inline double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/// Distance from p to the closed triangle (a, b, c), which may be degenerate.
inline double distance_to_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  double d = std::min({distance_to_segment(p, a, b), distance_to_segment(p, b, c), distance_to_segment(p, c, a)});
  const Eigen::Vector3d n = (b - a).cross(c - a);
  if (n.squaredNorm() > 1e-300) {
    const Eigen::Vector3d un = n.normalized();
    const Eigen::Vector3d q = p - (p - a).dot(un) * un;  // projection onto the plane
    const bool inside = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                        (a - c).cross(q - c).dot(n) >= 0;
    if (inside) d = std::min(d, (p - q).norm());
  }
  return d;
}

}  // namespace reconfig::testing
