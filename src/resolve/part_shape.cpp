#include "reconfig/resolve/part_shape.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <utility>
#include <numeric>

namespace reconfig::resolve {
namespace {

/// A third of the area of the faces around each vertex.
std::vector<double> vertex_areas(const geometry::Mesh& mesh) {
  std::vector<double> area(mesh.vertex_count(), 0.0);
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int k = 0; k < 3; ++k) area[mesh.F(f, k)] += third;
  }
  return area;
}

std::vector<std::array<int, 3>> face_neighbors(const geometry::Mesh& mesh) {
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;  // edge → (face, k)
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.F(f, k), v = mesh.F(f, (k + 1) % 3);
      edges[{std::min(u, v), std::max(u, v)}].emplace_back(f, k);
    }
  std::vector<std::array<int, 3>> neighbors(mesh.face_count(), {-1, -1, -1});
  for (const auto& [edge, faces] : edges)
    if (faces.size() == 2) {
      neighbors[faces[0].first][faces[0].second] = faces[1].first;
      neighbors[faces[1].first][faces[1].second] = faces[0].first;
    }
  return neighbors;
}

/// Whether the faces across every edge (`neighbors`, all ≥ 0) run it in the opposite direction.
bool consistently_oriented(const geometry::Mesh& mesh, const std::vector<std::array<int, 3>>& neighbors) {
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = neighbors[f][k], u = mesh.F(f, k), v = mesh.F(f, (k + 1) % 3);
      bool opposite = false;
      for (int l = 0; l < 3; ++l) opposite = opposite || (mesh.F(g, l) == v && mesh.F(g, (l + 1) % 3) == u);
      if (!opposite) return false;
    }
  return true;
}

}  // namespace

PartShape::PartShape(const geometry::Mesh& mesh, int max_samples) : distance(mesh), bounds(distance.tree().bounds()) {
  const std::vector<double> area = vertex_areas(mesh);
  const int n = mesh.vertex_count();
  const int stride = std::max(1, (n + std::max(1, max_samples) - 1) / std::max(1, max_samples));
  // A strided sample stands for the vertices it skips: it takes their area.
  for (int i = 0; i < n; i += stride) {
    double weight = 0;
    for (int j = i; j < std::min(n, i + stride); ++j) weight += area[j];
    if (weight <= 0) continue;
    sample_points.push_back(mesh.V.row(i).transpose());
    sample_weights.push_back(weight);
  }
  neighbors = face_neighbors(mesh);
  // From the tree's own copy of the corners: the very doubles the contour's exact tests get.
  planes.reserve(tree().leaf_corners().size());
  for (const geometry::TriangleCorners& t : tree().leaf_corners()) planes.push_back(geometry::certain_plane(t[0], t[1], t[2]));
  closed = std::all_of(neighbors.begin(), neighbors.end(),
                       [](const std::array<int, 3>& across) { return across[0] >= 0 && across[1] >= 0 && across[2] >= 0; });
  oriented = closed && consistently_oriented(mesh, neighbors);
  const double total = std::accumulate(sample_weights.begin(), sample_weights.end(), 0.0);
  if (total > 0)
    for (double& w : sample_weights) w /= total;
}

}  // namespace reconfig::resolve
