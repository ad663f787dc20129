#pragma once
/// @file
/// A part's signed distance sampled once on a dense grid in its own frame, for the many
/// look-ups of a sweep.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
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
  float nearest(const Eigen::Vector3d& x) const {
    const int i = int(std::floor(x.x() + 0.5)) - lo_.x(), j = int(std::floor(x.y() + 0.5)) - lo_.y(),
              k = int(std::floor(x.z() + 0.5)) - lo_.z();
    const bool in_box =
        unsigned(i) < unsigned(size_.x()) && unsigned(j) < unsigned(size_.y()) && unsigned(k) < unsigned(size_.z());
    const float value = in_box ? values_[index(i, j, k)] : float(band_);
    if (value < float(band_)) return value;
    return std::max(value, float((x - center_).norm() * h_ - radius_));
  }

  /// A lower bound of the distance from the world point x·h to the part's solid (0 inside):
  /// D² − |y|² is concave (D² is a minimum of |y − s|² over the solid's points s), so the
  /// trilinear interpolant of D² at the 8 grid points around x, minus the interpolant's
  /// variance Σ w_c |x − c|² h², is at most D²(x); the result is the square root of that,
  /// and never less than `nearest(x)` minus the distance to that grid point. Exact for a plane
  /// through grid points along an axis; within h²/(8 D) of D elsewhere on flat walls.
  double lower_bound(const Eigen::Vector3d& x) const;

  /// The cheap lower bound of φ at x·h: `nearest(x)` minus the distance to that grid point.
  double nearest_lower_bound(const Eigen::Vector3d& x) const {
    return double(nearest(x)) - (x - (x.array() + 0.5).floor().matrix()).norm() * h_;
  }

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
