#include "reconfig/geometry/primitives.h"

#include <cassert>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace reconfig::geometry {

Mesh make_box(const Eigen::Vector3d& size) {
  assert((size.array() > 0).all());
  Mesh mesh;
  mesh.V.resize(8, 3);
  for (int i = 0; i < 8; ++i)  // bit k of i chooses the high side along axis k
    for (int k = 0; k < 3; ++k) mesh.V(i, k) = ((i >> k) & 1 ? 0.5 : -0.5) * size[k];
  // Two triangles per side, counter-clockwise seen from outside.
  mesh.F.resize(12, 3);
  mesh.F << 0, 2, 3, 0, 3, 1,  // z = low  (normal -z)
      4, 5, 7, 4, 7, 6,        // z = high (normal +z)
      0, 1, 5, 0, 5, 4,        // y = low  (normal -y)
      2, 6, 7, 2, 7, 3,        // y = high (normal +y)
      0, 4, 6, 0, 6, 2,        // x = low  (normal -x)
      1, 3, 7, 1, 7, 5;        // x = high (normal +x)
  return mesh;
}

Mesh make_cylinder(double radius, double height, int segments) {
  assert(radius > 0 && height > 0 && segments >= 3);
  const int n = segments;
  Mesh mesh;
  mesh.V.resize(2 * n + 2, 3);
  const double h = height / 2;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n;
    const double x = radius * std::cos(angle), y = radius * std::sin(angle);
    mesh.V.row(i) << x, y, -h;      // bottom ring
    mesh.V.row(n + i) << x, y, h;   // top ring
  }
  const int bottom = 2 * n, top = 2 * n + 1;
  mesh.V.row(bottom) << 0, 0, -h;
  mesh.V.row(top) << 0, 0, h;
  mesh.F.resize(4 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.F.row(4 * i + 0) << i, j, n + j;  // side, seen from outside: counter-clockwise
    mesh.F.row(4 * i + 1) << i, n + j, n + i;
    mesh.F.row(4 * i + 2) << bottom, j, i;  // bottom cap faces -z
    mesh.F.row(4 * i + 3) << top, n + i, n + j;  // top cap faces +z
  }
  return mesh;
}

Mesh make_sphere(double radius, int subdivisions) {
  assert(radius > 0 && subdivisions >= 0 && subdivisions <= 8);
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Eigen::Vector3i> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (auto& v : vertices) v.normalize();
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoint_of;  // edge (low, high) → new vertex
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key = std::minmax(a, b);
      const auto [it, inserted] = midpoint_of.try_emplace(key, static_cast<int>(vertices.size()));
      if (inserted) vertices.push_back((vertices[static_cast<std::size_t>(a)] + vertices[static_cast<std::size_t>(b)]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.emplace_back(f[0], ab, ca);
      finer.emplace_back(f[1], bc, ab);
      finer.emplace_back(f[2], ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    faces = std::move(finer);
  }
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = radius * vertices[i].transpose();
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) mesh.F.row(static_cast<Eigen::Index>(i)) = faces[i].transpose();
  return mesh;
}

}  // namespace reconfig::geometry
