#include "reconfig/sculpt/mesh_index.h"

#include <algorithm>
#include <cmath>

#include "sculpt/detail/sort_unique.h"

namespace reconfig::sculpt {
namespace {

constexpr int kCellLimit = (1 << 20) - 1;  ///< cell coordinates are clamped to ±this (21 bits each)
constexpr int kEdgeSample = 4096;           ///< faces sampled for the mean edge length
/// The default cell edge in mean edge lengths: a tool's box then spans few cells (each a
/// hash look-up) and a cell holds a few hundred vertices of a surface.
constexpr double kEdgesPerCell = 8;

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
  vertex_faces_.reserve(V.rows());
  for (int v = 0; v < V.rows(); ++v) add_vertex(V.row(v).transpose());
  for (int f = 0; f < F.rows(); ++f)
    for (int i = 0; i < 3; ++i) vertex_faces_[F(f, i)].push_back(f);
  faces_ = static_cast<int>(F.rows());
}

std::array<int, 3> MeshIndex::cell_of(const Eigen::Vector3d& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) {
    const double x = std::floor(p[k] / cell_);
    c[k] = x >= kCellLimit ? kCellLimit : x <= -kCellLimit ? -kCellLimit : static_cast<int>(x);  // NaN: −limit
  }
  return c;
}

std::int64_t MeshIndex::key(const std::array<int, 3>& c) {
  std::int64_t k = 0;
  for (int i = 0; i < 3; ++i) k = (k << 21) | static_cast<std::int64_t>(c[i] + kCellLimit);
  return k;
}

std::vector<int> MeshIndex::vertices_in(const Eigen::AlignedBox3d& box, const Eigen::Ref<const Eigen::MatrixX3d>& V) const {
  std::vector<int> found;
  if (box.isEmpty() || high_[0] < low_[0]) return found;
  std::array<int, 3> from = cell_of(box.min()), to = cell_of(box.max());
  double cells = 1;
  for (int k = 0; k < 3; ++k) {
    from[k] = std::max(from[k], low_[k]);
    to[k] = std::min(to[k], high_[k]);
    if (to[k] < from[k]) return found;
    cells *= to[k] - from[k] + 1;
  }
  const auto collect = [&](const std::vector<int>& bucket) {
    for (int v : bucket)
      if (box.contains(V.row(v).transpose())) found.push_back(v);
  };
  if (cells > static_cast<double>(cells_.size())) {  // a box wider than the mesh: every occupied cell
    for (const auto& [k, bucket] : cells_) collect(bucket);
  } else {
    for (int x = from[0]; x <= to[0]; ++x)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int z = from[2]; z <= to[2]; ++z) {
          if (const auto at = cells_.find(key({x, y, z})); at != cells_.end()) collect(at->second);
        }
  }
  detail::sort_unique(found, static_cast<int>(V.rows()));
  return found;
}

void MeshIndex::move_vertex(int v, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const std::array<int, 3> c = cell_of(to);
  const std::int64_t old_key = key(cell_of(from)), new_key = key(c);
  if (old_key == new_key) return;
  std::vector<int>& old_bucket = cells_[old_key];
  old_bucket.erase(std::find(old_bucket.begin(), old_bucket.end(), v));
  if (old_bucket.empty()) cells_.erase(old_key);
  cells_[new_key].push_back(v);
  for (int k = 0; k < 3; ++k) {
    low_[k] = std::min(low_[k], c[k]);
    high_[k] = std::max(high_[k], c[k]);
  }
}

void MeshIndex::add_vertex(const Eigen::Vector3d& p) {
  const int v = vertex_count();
  vertex_faces_.emplace_back();
  const std::array<int, 3> c = cell_of(p);
  cells_[key(c)].push_back(v);
  const bool first = high_[0] < low_[0];
  for (int k = 0; k < 3; ++k) {
    low_[k] = first ? c[k] : std::min(low_[k], c[k]);
    high_[k] = first ? c[k] : std::max(high_[k], c[k]);
  }
}

void MeshIndex::change_face(int f, const std::array<int, 3>& before, const std::array<int, 3>& after) {
  if (before[0] < 0) faces_ = std::max(faces_, f + 1);
  for (int v : before)
    if (v >= 0) erase(vertex_faces_[v], f);
  for (int v : after) vertex_faces_[v].push_back(f);
}

}  // namespace reconfig::sculpt
