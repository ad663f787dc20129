#include "sweep/detail/clearance_check.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace reconfig::sweep::detail {
namespace {

/// f(s, t) = Σ λ_i L2_i − Σ λ_i |w_i − q|² with w_0 = 0, w_1, w_2 the corners relative to the
/// first one, λ = (1 − s − t, s, t) and q = s w_1 + t w_2.
struct TriangleQuadratic {
  Eigen::Vector3d w1, w2;
  double L2[3];
  double at(double s, double t) const {
    const Eigen::Vector3d q = s * w1 + t * w2;
    return (1 - s - t) * L2[0] + s * L2[1] + t * L2[2] - s * w1.squaredNorm() - t * w2.squaredNorm() + q.squaredNorm();
  }
  /// The minimum over the segment from (s0, t0) to (s1, t1) of the quadratic restricted to it.
  double segment_minimum(double s0, double t0, double s1, double t1) const {
    const double f0 = at(s0, t0), f1 = at(s1, t1), half = at(0.5 * (s0 + s1), 0.5 * (t0 + t1));
    const double a = 2 * (f0 + f1 - 2 * half), b = f1 - f0 - a;  // f(u) = a u² + b u + f0
    double best = std::min(f0, f1);
    if (a > 0) {
      const double u = std::clamp(-b / (2 * a), 0.0, 1.0);
      best = std::min(best, at(s0 + u * (s1 - s0), t0 + u * (t1 - t0)));
    }
    return best;
  }
};

bool triangle_keeps_clear(const Eigen::Vector3d v[3], const double L[3], double threshold,
                          const DistanceLowerBound& lower_bound, int depth) {
  const double L2[3] = {L[0] * L[0], L[1] * L[1], L[2] * L[2]};
  if (std::min({L[0], L[1], L[2]}) > threshold && squared_distance_lower_bound(v, L2) > threshold * threshold)
    return true;
  if (depth == 0) return false;
  const Eigen::Vector3d m[3] = {0.5 * (v[0] + v[1]), 0.5 * (v[1] + v[2]), 0.5 * (v[2] + v[0])};
  const double Lm[3] = {lower_bound(m[0]), lower_bound(m[1]), lower_bound(m[2])};
  const Eigen::Vector3d children[4][3] = {{v[0], m[0], m[2]}, {m[0], v[1], m[1]}, {m[2], m[1], v[2]}, {m[0], m[1], m[2]}};
  const double child_bounds[4][3] = {{L[0], Lm[0], Lm[2]}, {Lm[0], L[1], Lm[1]}, {Lm[2], Lm[1], L[2]}, {Lm[0], Lm[1], Lm[2]}};
  for (int c = 0; c < 4; ++c)
    if (!triangle_keeps_clear(children[c], child_bounds[c], threshold, lower_bound, depth - 1)) return false;
  return true;
}

}  // namespace

double squared_distance_lower_bound(const Eigen::Vector3d v[3], const double L2[3]) {
  const TriangleQuadratic f{v[1] - v[0], v[2] - v[0], {L2[0], L2[1], L2[2]}};
  double best = std::min({f.segment_minimum(0, 0, 1, 0), f.segment_minimum(1, 0, 0, 1), f.segment_minimum(0, 1, 0, 0)});
  // The stationary point: ∇f = 0 ⇔ 2 G (s, t) = (|w1|² − (L2_1 − L2_0), |w2|² − (L2_2 − L2_0)).
  const double g11 = f.w1.squaredNorm(), g12 = f.w1.dot(f.w2), g22 = f.w2.squaredNorm();
  const double det = g11 * g22 - g12 * g12;
  if (det > 1e-14 * g11 * g22) {
    const double r1 = 0.5 * (g11 - (L2[1] - L2[0])), r2 = 0.5 * (g22 - (L2[2] - L2[0]));
    const double s = (g22 * r1 - g12 * r2) / det, t = (g11 * r2 - g12 * r1) / det;
    if (s >= 0 && t >= 0 && s + t <= 1) best = std::min(best, f.at(s, t));
  }
  return best;
}

bool mesh_keeps_clear(const geometry::Mesh& mesh, const std::optional<Eigen::AlignedBox3d>& region, double threshold,
                      const DistanceLowerBound& lower_bound, int max_depth) {
  std::vector<double> bounds(std::size_t(mesh.vertex_count()), -1);
  std::vector<char> needed(bounds.size(), region ? 0 : 1);
  const auto in_region = [&](int f) {
    Eigen::AlignedBox3d box;
    for (int c = 0; c < 3; ++c) box.extend(mesh.V.row(mesh.F(f, c)).transpose());
    return !region || region->intersects(box);
  };
  for (int f = 0; f < mesh.face_count() && region; ++f)
    if (in_region(f))
      for (int c = 0; c < 3; ++c) needed[std::size_t(mesh.F(f, c))] = 1;
  tbb::parallel_for(0, mesh.vertex_count(), [&](int v) {
    if (needed[std::size_t(v)]) bounds[std::size_t(v)] = lower_bound(mesh.V.row(v).transpose());
  });
  std::atomic<bool> clear{true};
  tbb::parallel_for(0, mesh.face_count(), [&](int f) {
    if (!clear || !in_region(f)) return;
    Eigen::Vector3d v[3];
    double L[3];
    for (int c = 0; c < 3; ++c) {
      v[c] = mesh.V.row(mesh.F(f, c)).transpose();
      L[c] = bounds[std::size_t(mesh.F(f, c))];
    }
    if (!triangle_keeps_clear(v, L, threshold, lower_bound, max_depth)) clear = false;
  });
  return clear;
}

}  // namespace reconfig::sweep::detail
