#include "reconfig/geometry/signed_distance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "reconfig/geometry/closest_point_on_triangle.h"

namespace reconfig::geometry {
namespace {

std::uint64_t edge_key(int u, int v) {
  if (u > v) std::swap(u, v);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(v);
}

/// The interior angle at corner `at` of a triangle with corners at, p, r.
double corner_angle(const Eigen::Vector3d& at, const Eigen::Vector3d& p, const Eigen::Vector3d& r) {
  const Eigen::Vector3d u = p - at, w = r - at;
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

}  // namespace

MeshSignedDistance::MeshSignedDistance(const Mesh& mesh) : tree_(mesh.V, mesh.F) {
  const int nf = mesh.face_count();
  face_normals_.resize(nf);
  vertex_normals_.assign(mesh.vertex_count(), Eigen::Vector3d::Zero());
  std::unordered_map<std::uint64_t, Eigen::Vector3d> edge_sums;
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    face_normals_[f] = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
    vertex_normals_[mesh.F(f, 0)] += corner_angle(a, b, c) * face_normals_[f];
    vertex_normals_[mesh.F(f, 1)] += corner_angle(b, c, a) * face_normals_[f];
    vertex_normals_[mesh.F(f, 2)] += corner_angle(c, a, b) * face_normals_[f];
    for (int k = 0; k < 3; ++k)  // (Eigen leaves a default-constructed vector uninitialized)
      edge_sums.try_emplace(edge_key(mesh.F(f, k), mesh.F(f, (k + 1) % 3)), Eigen::Vector3d::Zero())
          .first->second += face_normals_[f];
  }
  edge_normals_.resize(nf);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) edge_normals_[f][k] = edge_sums.at(edge_key(mesh.F(f, k), mesh.F(f, (k + 1) % 3)));
}

Eigen::Vector3d MeshSignedDistance::pseudonormal(int f, const Eigen::Vector3d& q) const {
  const Eigen::MatrixX3d& V = tree_.vertices();
  const Eigen::MatrixX3i& F = tree_.faces();
  const TriangleClosestPoint c =
      closest_point_on_triangle(q, V.row(F(f, 0)).transpose(), V.row(F(f, 1)).transpose(), V.row(F(f, 2)).transpose());
  switch (c.feature) {
    case TriangleFeature::kFace: return face_normals_[f];
    case TriangleFeature::kEdge01: return edge_normals_[f][0];
    case TriangleFeature::kEdge12: return edge_normals_[f][1];
    case TriangleFeature::kEdge20: return edge_normals_[f][2];
    case TriangleFeature::kVertex0: return vertex_normals_[F(f, 0)];
    case TriangleFeature::kVertex1: return vertex_normals_[F(f, 1)];
    case TriangleFeature::kVertex2: return vertex_normals_[F(f, 2)];
  }
  return face_normals_[f];
}

MeshSignedDistance::Query MeshSignedDistance::query(const Eigen::Vector3d& q, double max_distance) const {
  const TriangleBvh::Nearest nearest = tree_.nearest(q, max_distance);
  if (nearest.triangle < 0) return {};
  const double d = std::sqrt(nearest.squared_distance);
  const bool inside = (q - nearest.point).dot(pseudonormal(nearest.triangle, q)) < 0;
  return {inside ? -d : d, nearest.point, nearest.triangle};
}

}  // namespace reconfig::geometry
