#pragma once
/// @file
/// A part's signed distance sampled once on a dense grid in its own frame, for the many
/// look-ups of a sweep.

#include <Eigen/Core>

#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::sweep::detail {

/// φ at the points (i, j, k)·h of a box around the part grown by `band`: the exact distance to
/// the nearest triangle (triangle tree) where it is below `band` outside (`inner_band` inside),
/// else that band; negative inside,
/// the side from the parity of the surface crossings along the grid row in x (an edge shared by
/// two triangles counts for exactly one of them), not from pseudonormals.
class PartDistance {
 public:
  /// @param part  closed mesh, #V×3 and #F×3
  /// @param h     > 0, grid step
  /// @param band        > 0, outside, in scene units
  /// @param inner_band  > 0, inside (a sweep needs little depth: φ only matters near its level)
  PartDistance(const geometry::Mesh& part, double h, double band, double inner_band);

  /// φ (clamped to [−inner_band, band]; beyond the box, the larger of band and the distance to the part's
  /// bounding ball: lower bounds of φ) at the grid point nearest to the
  /// index-space point x (world point x·h).
  float nearest(const Eigen::Vector3d& x) const;

 private:
  std::size_t index(int i, int j, int k) const { return (std::size_t(i) * size_.y() + j) * size_.z() + k; }
  void compute_signs(const geometry::Mesh& part, std::vector<char>& inside) const;
  void compute_distances(const geometry::Mesh& part, const std::vector<char>& inside);

  double h_ = 1, band_ = 1, inner_band_ = 1, radius_ = 0;
  Eigen::Vector3d center_ = Eigen::Vector3d::Zero();  ///< index space
  Eigen::Vector3i lo_ = Eigen::Vector3i::Zero(), size_ = Eigen::Vector3i::Zero();
  std::vector<float> values_;
};

}  // namespace reconfig::sweep::detail
