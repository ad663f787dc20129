#include "sweep/detail/part_distance.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "reconfig/geometry/closest_point_on_triangle.h"
#include "reconfig/geometry/triangle_bvh.h"

namespace reconfig::sweep::detail {
namespace {

/// (b − a) × (p − a) in the yz plane, computed with the edge's endpoints in index order so
/// that the two faces of a shared edge get exactly opposite values; `forward` says whether the
/// face runs a → b in that order.
Eigen::Vector3d closest_point(const geometry::Mesh& part, int f, const Eigen::Vector3d& q) {
  return geometry::closest_point_on_triangle(q, part.V.row(part.F(f, 0)).transpose(), part.V.row(part.F(f, 1)).transpose(),
                                             part.V.row(part.F(f, 2)).transpose())
      .point;
}

double edge_function(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p, bool forward) {
  const double value = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  return forward ? value : -value;
}

}  // namespace

PartDistance::PartDistance(const geometry::Mesh& part, double h, double band, double inner_band)
    : h_(h), band_(band), inner_band_(inner_band) {
  const Eigen::Vector3d min = part.V.colwise().minCoeff(), max = part.V.colwise().maxCoeff();
  center_ = 0.5 * (min + max) / h;
  radius_ = (part.V.rowwise() - (0.5 * (min + max)).transpose()).rowwise().norm().maxCoeff();
  lo_ = ((min.array() - band) / h).floor().cast<int>();
  const Eigen::Vector3i hi = ((max.array() + band) / h).ceil().cast<int>();
  size_ = hi - lo_ + Eigen::Vector3i::Ones();
  std::vector<char> inside(std::size_t(size_.prod()), 0);
  compute_signs(part, inside);
  values_.resize(inside.size());
  compute_distances(part, inside);
}

void PartDistance::compute_distances(const geometry::Mesh& part, const std::vector<char>& inside) {
  const geometry::TriangleBvh tree(part.V, part.F);
  // Row by row along z: the triangle nearest to the previous point bounds the distance from
  // above (nearly tight: a tight start for the search), and a point with no triangle within
  // its band plus m steps puts the next m points beyond their bands too (distances are
  // 1-Lipschitz).
  constexpr int kSkip = 4;
  const double outer_limit = std::max(band_, inner_band_);
  tbb::parallel_for(0, size_.x() * size_.y(), [&](int row) {
    const int i = row / size_.y(), j = row % size_.y();
    int seed = -1;        // the nearest triangle to the last point that found one
    int beyond_until = -1;  // points up to this one lie beyond their bands
    for (int k = 0; k < size_.z(); ++k) {
      const bool in = inside[index(i, j, k)];
      const double limit = in ? inner_band_ : band_;
      double distance = limit;
      const Eigen::Vector3d q = (lo_ + Eigen::Vector3i(i, j, k)).cast<double>() * h_;
      if (k <= beyond_until) {
      } else if (seed >= 0) {
        const double upper = std::min(limit, (q - closest_point(part, seed, q)).norm());
        const geometry::TriangleBvh::Nearest hit = tree.nearest(q, upper * (1 + 1e-12));
        distance = hit.triangle < 0 ? upper : std::sqrt(hit.squared_distance);
        if (hit.triangle >= 0) seed = hit.triangle;
      } else {
        const geometry::TriangleBvh::Nearest hit = tree.nearest(q, outer_limit + kSkip * h_);
        if (hit.triangle < 0) beyond_until = k + kSkip;
        else distance = std::sqrt(hit.squared_distance);
        seed = hit.triangle;
      }
      values_[index(i, j, k)] = float(in ? -std::min(distance, limit) : std::min(distance, limit));
    }
  });
}

void PartDistance::compute_signs(const geometry::Mesh& part, std::vector<char>& inside) const {
  // Per grid row (j, k) along x: the x of every crossing with the surface.
  std::vector<std::vector<double>> crossings(std::size_t(size_.y()) * size_.z());
  for (int f = 0; f < part.face_count(); ++f) {
    int v[3] = {part.F(f, 0), part.F(f, 1), part.F(f, 2)};
    Eigen::Vector3d p[3];
    for (int c = 0; c < 3; ++c) p[c] = part.V.row(v[c]).transpose() / h_;
    const double normal_x = (p[1] - p[0]).cross(p[2] - p[0]).x();
    if (normal_x == 0) continue;  // parallel to the rows
    const int j0 = std::max(0, int(std::ceil(std::min({p[0].y(), p[1].y(), p[2].y()}))) - lo_.y());
    const int j1 = std::min(size_.y() - 1, int(std::floor(std::max({p[0].y(), p[1].y(), p[2].y()}))) - lo_.y());
    const int k0 = std::max(0, int(std::ceil(std::min({p[0].z(), p[1].z(), p[2].z()}))) - lo_.z());
    const int k1 = std::min(size_.z() - 1, int(std::floor(std::max({p[0].z(), p[1].z(), p[2].z()}))) - lo_.z());
    const double orientation = normal_x > 0 ? 1 : -1;
    for (int j = j0; j <= j1; ++j)
      for (int k = k0; k <= k1; ++k) {
        const Eigen::Vector2d q(lo_.y() + j, lo_.z() + k);
        double w[3];
        bool covered = true;
        for (int c = 0; c < 3 && covered; ++c) {
          const int a = v[c], b = v[(c + 1) % 3];
          const Eigen::Vector3d& pa = a < b ? p[c] : p[(c + 1) % 3];
          const Eigen::Vector3d& pb = a < b ? p[(c + 1) % 3] : p[c];
          const double e = orientation * edge_function({pa.y(), pa.z()}, {pb.y(), pb.z()}, q, a < b);
          // On an edge: one of two faces seen from the same side counts it, both or neither of two
          // folded over it (a silhouette), so the parity stays right.
          covered = e > 0 || (e == 0 && (a < b) == (orientation > 0));
          w[(c + 2) % 3] = e;
        }
        if (!covered) continue;
        const double total = w[0] + w[1] + w[2];
        const double x = total == 0 ? p[0].x() : (w[0] * p[0].x() + w[1] * p[1].x() + w[2] * p[2].x()) / total;
        crossings[std::size_t(j) * size_.z() + k].push_back(x);
      }
  }
  tbb::parallel_for(0, size_.y(), [&](int j) {
    for (int k = 0; k < size_.z(); ++k) {
      std::vector<double>& xs = crossings[std::size_t(j) * size_.z() + k];
      std::sort(xs.begin(), xs.end());
      std::size_t passed = 0;
      for (int i = 0; i < size_.x(); ++i) {
        const double x = lo_.x() + i;
        while (passed < xs.size() && xs[passed] < x) ++passed;
        inside[index(i, j, k)] = passed % 2 == 1;
      }
    }
  });
}

double PartDistance::lower_bound(const Eigen::Vector3d& x) const {
  const double from_nearest = nearest_lower_bound(x);
  const Eigen::Vector3d base = x.array().floor().matrix();
  const Eigen::Vector3i corner = base.cast<int>() - lo_;
  if ((corner.array() < 0).any() || (corner.array() + 1 >= size_.array()).any())
    return std::max(from_nearest, 0.0) * (1 - 1e-6);
  const Eigen::Vector3d t = x - base;
  double interpolated = 0;
  for (int c = 0; c < 8; ++c) {
    const int di = c >> 2, dj = (c >> 1) & 1, dk = c & 1;
    const double weight = (di ? t.x() : 1 - t.x()) * (dj ? t.y() : 1 - t.y()) * (dk ? t.z() : 1 - t.z());
    const double value = std::max(0.0f, values_[index(corner.x() + di, corner.y() + dj, corner.z() + dk)]);
    interpolated += weight * value * value;
  }
  const double variance = (t.x() * (1 - t.x()) + t.y() * (1 - t.y()) + t.z() * (1 - t.z())) * h_ * h_;
  // (1 − 10⁻⁶): the grid's values are floats, rounded either way.
  return std::max(from_nearest, std::sqrt(std::max(0.0, interpolated - variance))) * (1 - 1e-6);
}

}  // namespace reconfig::sweep::detail
