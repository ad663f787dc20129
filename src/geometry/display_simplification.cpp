#include "reconfig/geometry/display_simplification.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace reconfig::geometry {

Mesh cluster_vertices(const Mesh& mesh, double cell) {
  Mesh out;
  if (mesh.V.rows() == 0) return mesh;
  const Eigen::RowVector3d origin = mesh.V.colwise().minCoeff();
  std::unordered_map<long long, int> cluster_of_cell;
  std::vector<int> cluster(mesh.V.rows());
  std::vector<Eigen::Vector3d> sums;
  std::vector<int> counts;
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Array3d grid = ((mesh.V.row(v) - origin) / cell).array().floor().transpose();
    // 21 bits per axis: plenty for the cell sizes display simplification uses.
    const long long key = (static_cast<long long>(grid.x()) << 42) | (static_cast<long long>(grid.y()) << 21) |
                          static_cast<long long>(grid.z());
    const auto [it, added] = cluster_of_cell.try_emplace(key, static_cast<int>(sums.size()));
    if (added) {
      sums.emplace_back(Eigen::Vector3d::Zero());
      counts.push_back(0);
    }
    cluster[v] = it->second;
    sums[it->second] += mesh.V.row(v).transpose();
    ++counts[it->second];
  }
  out.V.resize(static_cast<Eigen::Index>(sums.size()), 3);
  for (std::size_t c = 0; c < sums.size(); ++c) out.V.row(static_cast<Eigen::Index>(c)) = sums[c].transpose() / counts[c];
  std::vector<std::array<int, 3>> triangles;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const std::array<int, 3> t{cluster[mesh.F(f, 0)], cluster[mesh.F(f, 1)], cluster[mesh.F(f, 2)]};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
  // The same triangle (same corners, same orientation) once: rotate its smallest corner first.
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
  out.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    out.F.row(static_cast<Eigen::Index>(f)) << triangles[f][0], triangles[f][1], triangles[f][2];
  return out;
}

Mesh simplify_for_display(const Mesh& mesh, int max_triangles) {
  if (mesh.F.rows() <= max_triangles || mesh.V.rows() == 0) return mesh;
  const double size = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).maxCoeff();
  // Bisect the cell size between "too fine" and "fine enough" (one cell: nothing left).
  double fine = size * 1e-6, coarse = size * 1.01;
  Mesh best = cluster_vertices(mesh, coarse);
  for (int step = 0; step < 30 && coarse / fine > 1.05; ++step) {
    const double middle = std::sqrt(fine * coarse);
    Mesh candidate = cluster_vertices(mesh, middle);
    if (candidate.F.rows() <= max_triangles) {
      coarse = middle;
      best = std::move(candidate);
    } else {
      fine = middle;
    }
  }
  return best;
}

}  // namespace reconfig::geometry
