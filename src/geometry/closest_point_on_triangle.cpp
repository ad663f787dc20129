#include "reconfig/geometry/closest_point_on_triangle.h"

#include <Eigen/Geometry>

namespace reconfig::geometry {
namespace {

/// The nearest point of segment [p, r] to q, labelled `at_p`, `at_r` at its ends, else `edge`.
TriangleClosestPoint closest_on_segment(const Eigen::Vector3d& q, const Eigen::Vector3d& p, const Eigen::Vector3d& r,
                                        TriangleFeature edge, TriangleFeature at_p, TriangleFeature at_r) {
  const Eigen::Vector3d d = r - p;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? (q - p).dot(d) / len2 : 0.0;
  if (s <= 0) return {p, at_p};
  if (s >= 1) return {r, at_r};
  return {p + s * d, edge};
}

/// Degenerate triangle: the best of its three edges.
TriangleClosestPoint closest_on_edges(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c) {
  using F = TriangleFeature;
  const TriangleClosestPoint candidates[3] = {closest_on_segment(q, a, b, F::kEdge01, F::kVertex0, F::kVertex1),
                                              closest_on_segment(q, b, c, F::kEdge12, F::kVertex1, F::kVertex2),
                                              closest_on_segment(q, c, a, F::kEdge20, F::kVertex2, F::kVertex0)};
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if ((candidates[i].point - q).squaredNorm() < (candidates[best].point - q).squaredNorm()) best = i;
  return candidates[best];
}

}  // namespace

TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  using F = TriangleFeature;
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = q - a;
  // Collinear or coincident corners (relative test; also true when an edge has length 0).
  if (ab.cross(ac).squaredNorm() <= 1e-30 * ab.squaredNorm() * ac.squaredNorm()) return closest_on_edges(q, a, b, c);
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {a, F::kVertex0};
  const Eigen::Vector3d bp = q - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {b, F::kVertex1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return {a + d1 / (d1 - d3) * ab, F::kEdge01};
  const Eigen::Vector3d cp = q - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {c, F::kVertex2};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return {a + d2 / (d2 - d6) * ac, F::kEdge20};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return {b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b), F::kEdge12};
  const double denom = 1.0 / (va + vb + vc);
  return {a + ab * (vb * denom) + ac * (vc * denom), F::kFace};
}

}  // namespace reconfig::geometry
