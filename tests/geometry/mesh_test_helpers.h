#pragma once
/// @file
/// Helpers shared by the mesh I/O, check and mass-property tests, and those that build a mesh
/// from others.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numeric>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry::testing {

/// `mesh` with vertices sorted lexicographically, each face rotated to start at its lowest
/// index (keeping orientation), faces sorted: equal for two meshes that differ only in vertex
/// and face numbering.
inline Mesh canonical(const Mesh& mesh) {
  const int n = mesh.vertex_count();
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  auto row = [&](int v) { return std::array<double, 3>{mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2)}; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return row(a) < row(b); });
  std::vector<int> rank(static_cast<std::size_t>(n));
  Mesh out;
  out.V.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
    out.V.row(i) = mesh.V.row(order[static_cast<std::size_t>(i)]);
  }
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < mesh.face_count(); ++f) {
    std::array<int, 3> t{rank[static_cast<std::size_t>(mesh.F(f, 0))], rank[static_cast<std::size_t>(mesh.F(f, 1))],
                         rank[static_cast<std::size_t>(mesh.F(f, 2))]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  out.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) out.F(static_cast<Eigen::Index>(f), k) = faces[f][static_cast<std::size_t>(k)];
  return out;
}

/// `mesh` with every vertex mapped by `T`.
inline Mesh transformed(const Mesh& mesh, const Eigen::Affine3d& T) {
  Mesh out = mesh;
  for (int v = 0; v < mesh.vertex_count(); ++v) out.V.row(v) = (T * Eigen::Vector3d(mesh.V.row(v))).transpose();
  return out;
}

/// `a` and `b` in one mesh (b's vertices and faces after a's).
inline Mesh merge(const Mesh& a, const Mesh& b) {
  Mesh m;
  m.V.resize(a.vertex_count() + b.vertex_count(), 3);
  m.V << a.V, b.V;
  m.F.resize(a.face_count() + b.face_count(), 3);
  m.F << a.F, (b.F.array() + a.vertex_count()).matrix();
  return m;
}

/// `mesh` with every coordinate rounded to the nearest float (what STL and Assimp keep).
inline Mesh rounded_to_float(Mesh mesh) {
  mesh.V = mesh.V.cast<float>().cast<double>();
  return mesh;
}

inline bool same_mesh(const Mesh& a, const Mesh& b) {
  const Mesh ca = canonical(a), cb = canonical(b);
  return ca.V.rows() == cb.V.rows() && ca.F.rows() == cb.F.rows() && ca.V == cb.V && ca.F == cb.F;
}

/// Same vertex and face counts, and face f of `a` has corner k within `tolerance` of the
/// same corner of face f of `b` (face order and corner order kept, vertex numbering free).
inline bool same_faces_within(const Mesh& a, const Mesh& b, double tolerance) {
  if (a.vertex_count() != b.vertex_count() || a.face_count() != b.face_count()) return false;
  for (int f = 0; f < a.face_count(); ++f)
    for (int k = 0; k < 3; ++k)
      if ((a.V.row(a.F(f, k)) - b.V.row(b.F(f, k))).lpNorm<Eigen::Infinity>() > tolerance) return false;
  return true;
}

inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

/// ASCII PLY text of `mesh` (our writers do not do PLY; the tests need it as loader input).
inline std::string ply_text(const Mesh& mesh) {
  std::string s = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(mesh.vertex_count()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                  std::to_string(mesh.face_count()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  char buffer[128];
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g\n", mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2));
    s += buffer;
  }
  for (int f = 0; f < mesh.face_count(); ++f)
    s += "3 " + std::to_string(mesh.F(f, 0)) + " " + std::to_string(mesh.F(f, 1)) + " " +
         std::to_string(mesh.F(f, 2)) + "\n";
  return s;
}

/// OFF text of `mesh`.
inline std::string off_text(const Mesh& mesh) {
  std::string s = "OFF\n" + std::to_string(mesh.vertex_count()) + " " + std::to_string(mesh.face_count()) + " 0\n";
  char buffer[128];
  for (int v = 0; v < mesh.vertex_count(); ++v) {
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g\n", mesh.V(v, 0), mesh.V(v, 1), mesh.V(v, 2));
    s += buffer;
  }
  for (int f = 0; f < mesh.face_count(); ++f)
    s += "3 " + std::to_string(mesh.F(f, 0)) + " " + std::to_string(mesh.F(f, 1)) + " " +
         std::to_string(mesh.F(f, 2)) + "\n";
  return s;
}

}  // namespace reconfig::geometry::testing
