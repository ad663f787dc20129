#include "sweep/detail/outer_shells.h"

#include <Eigen/Geometry>

#include <numeric>
#include <vector>

namespace reconfig::sweep::detail {
namespace {

int find_root(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

geometry::Mesh outer_shells(const geometry::Mesh& mesh, int& removed) {
  std::vector<int> parent(mesh.vertex_count());
  std::iota(parent.begin(), parent.end(), 0);
  for (int f = 0; f < mesh.face_count(); ++f)
    for (int c = 1; c < 3; ++c) parent[find_root(parent, mesh.F(f, c))] = find_root(parent, mesh.F(f, 0));
  std::vector<double> volume(mesh.vertex_count(), 0.0);  // six times the signed volume, per root
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    volume[find_root(parent, mesh.F(f, 0))] += a.dot(b.cross(c));
  }
  removed = 0;
  for (int v = 0; v < mesh.vertex_count(); ++v) removed += parent[v] == v && volume[v] < 0;
  std::vector<int> new_index(mesh.vertex_count(), -1);
  geometry::Mesh kept;
  std::vector<Eigen::Vector3i> faces;
  int vertices = 0;
  for (int f = 0; f < mesh.face_count(); ++f) {
    if (volume[find_root(parent, mesh.F(f, 0))] < 0) continue;
    Eigen::Vector3i face;
    for (int c = 0; c < 3; ++c) {
      int& index = new_index[mesh.F(f, c)];
      if (index < 0) index = vertices++;
      face[c] = index;
    }
    faces.push_back(face);
  }
  kept.V.resize(vertices, 3);
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (new_index[v] >= 0) kept.V.row(new_index[v]) = mesh.V.row(v);
  kept.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) kept.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  return kept;
}

}  // namespace reconfig::sweep::detail
