#include "reconfig/sculpt/mesh_index.h"

#include <algorithm>
#include <cmath>

#include "sculpt/detail/sort_unique.h"

namespace reconfig::sculpt {
namespace {

constexpr int kEdgeSample = 4096;           ///< faces sampled for the mean edge length
/// The default cell edge in mean edge lengths: a cell then holds a few hundred vertices of a
/// surface, and a tool's box spans few cells.
constexpr double kEdgesPerCell = 8;
/// The grid spans the mesh's box widened by this fraction of its size on every side (room for
/// strokes to pull the surface out before vertices pile up in the border cells).
constexpr double kMargin = 0.25;
/// The grid has at most this many cells per vertex (or `kMinCellLimit`): coarser cells than
/// asked for if need be.
constexpr double kCellsPerVertex = 2;
constexpr double kMinCellLimit = 4096;

double mean_edge_length(const Eigen::Ref<const Eigen::MatrixX3d>& V, const Eigen::Ref<const Eigen::MatrixX3i>& F) {
  double sum = 0;
  int count = 0;
  const int faces = static_cast<int>(F.rows());
  const int step = std::max(1, faces / kEdgeSample);
  for (int f = 0; f < faces; f += step)
    for (int i = 0; i < 3; ++i, ++count) sum += (V.row(F(f, i)) - V.row(F(f, (i + 1) % 3))).norm();
  return count > 0 ? sum / count : 0;
}

void erase(std::vector<int>& list, int value) {
  const auto at = std::find(list.begin(), list.end(), value);
  if (at == list.end()) return;
  *at = list.back();
  list.pop_back();
}

}  // namespace

MeshIndex::MeshIndex(const Eigen::Ref<const Eigen::MatrixX3d>& V, const Eigen::Ref<const Eigen::MatrixX3i>& F,
                     double cell) {
  const double edge = mean_edge_length(V, F);
  cell_ = cell > 0 ? cell : edge > 0 ? kEdgesPerCell * edge : 1;
  Eigen::AlignedBox3d box;
  for (int v = 0; v < V.rows(); ++v)
    if (V.row(v).allFinite()) box.extend(Eigen::Vector3d(V.row(v)));
  const Eigen::Vector3d size = (1 + 2 * kMargin) * box.sizes();
  if (!box.isEmpty() && size.allFinite()) {
    origin_ = box.min() - kMargin * box.sizes();
    const double limit = std::max(kMinCellLimit, kCellsPerVertex * static_cast<double>(V.rows()));
    double grid_cell = cell_, cells = 0;
    for (;;) {
      cells = 1;
      for (int k = 0; k < 3; ++k) cells *= std::floor(size[k] / grid_cell) + 1;
      if (cells <= limit) break;
      grid_cell *= std::cbrt(cells / limit) * 1.01;
    }
    inverse_ = 1 / grid_cell;
    for (int k = 0; k < 3; ++k) dims_[k] = static_cast<int>(std::floor(size[k] / grid_cell)) + 1;
    cells_.assign(static_cast<std::size_t>(cells), {});
  }
  vertex_faces_.reserve(V.rows());
  for (int v = 0; v < V.rows(); ++v) add_vertex(V.row(v).transpose());
  for (int f = 0; f < F.rows(); ++f)
    for (int i = 0; i < 3; ++i) vertex_faces_[F(f, i)].push_back(f);
  faces_ = static_cast<int>(F.rows());
}

std::array<int, 3> MeshIndex::cell_of(const Eigen::Vector3d& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) {
    const double x = std::floor((p[k] - origin_[k]) * inverse_);
    c[k] = x >= dims_[k] - 1 ? dims_[k] - 1 : x > 0 ? static_cast<int>(x) : 0;  // NaN: 0
  }
  return c;
}

std::vector<int> MeshIndex::vertices_in(const Eigen::AlignedBox3d& box, const Eigen::Ref<const Eigen::MatrixX3d>& V) const {
  std::vector<int> found;
  if (box.isEmpty()) return found;
  const std::array<int, 3> from = cell_of(box.min()), to = cell_of(box.max());
  for (int x = from[0]; x <= to[0]; ++x)
    for (int y = from[1]; y <= to[1]; ++y)
      for (int z = from[2]; z <= to[2]; ++z)
        for (int v : cells_[cell_number({x, y, z})])
          if (box.contains(V.row(v).transpose())) found.push_back(v);
  detail::sort_unique(found, static_cast<int>(V.rows()));
  return found;
}

void MeshIndex::move_vertex(int v, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const int old_cell = cell_number(cell_of(from)), new_cell = cell_number(cell_of(to));
  if (old_cell == new_cell) return;
  erase(cells_[old_cell], v);
  cells_[new_cell].push_back(v);
}

void MeshIndex::add_vertex(const Eigen::Vector3d& p) {
  const int v = vertex_count();
  vertex_faces_.emplace_back();
  cells_[cell_number(cell_of(p))].push_back(v);
}

void MeshIndex::change_face(int f, const std::array<int, 3>& before, const std::array<int, 3>& after) {
  if (before[0] < 0) faces_ = std::max(faces_, f + 1);
  for (int v : before)
    if (v >= 0) erase(vertex_faces_[v], f);
  for (int v : after) vertex_faces_[v].push_back(f);
}

}  // namespace reconfig::sculpt
