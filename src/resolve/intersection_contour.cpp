#include "reconfig/resolve/intersection_contour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "reconfig/geometry/certain_plane.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::resolve {
namespace {

using Triangle = geometry::TriangleCorners;

/// The planes of a moved mesh's triangles (`certain_plane.h`), each computed once, when first
/// asked for, from the moved corners: a tree query meets each triangle in several pairs. Kept
/// by the triangle's position in its tree's leaf order (`PlacedPair::g_position`).
class MovedPlanes {
 public:
  explicit MovedPlanes(int face_count) : planes_(new geometry::CertainPlane[face_count]), known_(face_count, 0) {}

  /// The plane of the triangle at `position`, whose corners are `moved` (the same for every
  /// call with that position).
  const geometry::CertainPlane& operator()(int position, const Triangle& moved) {
    if (!known_[position]) {
      planes_[position] = geometry::certain_plane(moved[0], moved[1], moved[2]);
      known_[position] = 1;
    }
    return planes_[position];
  }

 private:
  std::unique_ptr<geometry::CertainPlane[]> planes_;
  std::vector<std::uint8_t> known_;
};

double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& e0, const Eigen::Vector3d& e1) {
  const Eigen::Vector3d d = e1 - e0;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((p - e0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (e0 + s * d - p).norm();
}

/// The edge (of either triangle) that point p of their intersection lies on, in a's frame:
/// (edge part, corner index k of edge k→k+1). Where p lies on several (a corner, or edges of
/// both triangles) the one crossing the other triangle's plane most steeply is taken: an edge
/// lying in that plane would make the slide of p along it unbounded. `normal`: the unit normals
/// of tb and ta, the planes that a's and b's edges cross.
std::pair<int, int> edge_through(const Eigen::Vector3d& p, const Triangle& ta, const Triangle& tb,
                                 const std::array<Eigen::Vector3d, 2>& normal) {
  std::array<double, 6> distance;
  double nearest = std::numeric_limits<double>::infinity();
  for (int e = 0; e < 6; ++e) {
    const Triangle& t = e < 3 ? ta : tb;
    distance[e] = distance_to_segment(p, t[e % 3], t[(e % 3 + 1) % 3]);
    nearest = std::min(nearest, distance[e]);
  }
  const double scale = 1 + p.cwiseAbs().maxCoeff();
  std::pair<int, int> best{0, 0};
  double steepest = -1;
  for (int e = 0; e < 6; ++e) {
    if (distance[e] > nearest + 1e-12 * scale) continue;
    const Triangle& t = e < 3 ? ta : tb;
    const Eigen::Vector3d d = t[(e % 3 + 1) % 3] - t[e % 3];
    const double crossing = d.norm() > 0 ? std::abs(normal[e / 3].dot(d)) / d.norm() : 0.0;
    if (crossing > steepest) {
      steepest = crossing;
      best = {e / 3, e % 3};
    }
  }
  return best;
}

struct PairContext {
  const PartShape& a;
  const PartShape& b;
  const Eigen::Isometry3d& place_a;  ///< a's frame → world
};

/// Two triangles that cross (faces fa of a and fb of b), in a's frame, with their unit normals.
struct CrossingPair {
  int fa = -1, fb = -1;
  const Triangle& ta;
  const Triangle& tb;
  Eigen::Vector3d na, nb;
};

ContourPoint contour_point(const PairContext& ctx, const Eigen::Vector3d& p, const CrossingPair& pair) {
  const auto& [fa, fb, ta, tb, na, nb] = pair;
  const auto [edge_part, k] = edge_through(p, ta, tb, {nb, na});
  const Triangle& edge_triangle = edge_part == 0 ? ta : tb;
  const Eigen::MatrixX3i& F = (edge_part == 0 ? ctx.a : ctx.b).tree().faces();
  const int f = edge_part == 0 ? fa : fb;
  ContourPoint point;
  point.position = ctx.place_a * p;
  point.edge_part = edge_part;
  point.edge = {std::min(F(f, k), F(f, (k + 1) % 3)), std::max(F(f, k), F(f, (k + 1) % 3))};
  point.triangle = edge_part == 0 ? fb : fa;
  const Eigen::Matrix3d R = ctx.place_a.linear();
  point.edge_direction = R * (edge_triangle[(k + 1) % 3] - edge_triangle[k]);
  point.plane_normal = R * (edge_part == 0 ? nb : na);
  return point;
}

/// The weight of the segment a triangle t (face f of `shape`) contributes against the plane
/// through p0 with unit normal n (see ContourSegment::weight): ½ or 0 when one of t's edges
/// lies in the plane, by the side of the face across that edge; 1 otherwise.
double edge_weight(const Triangle& t, int f, const PartShape& shape, const Eigen::Isometry3d& to_frame,
                   const Eigen::Vector3d& p0, const Eigen::Vector3d& n) {
  const double scale = 1 + std::max({t[0].cwiseAbs().maxCoeff(), t[1].cwiseAbs().maxCoeff(), t[2].cwiseAbs().maxCoeff()});
  const double eps = 1e-12 * scale;
  std::array<double, 3> side;
  for (int k = 0; k < 3; ++k) side[k] = n.dot(t[k] - p0);
  for (int k = 0; k < 3; ++k) {
    const int third = (k + 2) % 3;
    if (std::abs(side[k]) > eps || std::abs(side[(k + 1) % 3]) > eps || std::abs(side[third]) <= eps) continue;
    const int g = shape.neighbors[f][k];
    if (g < 0) return 1;  // an open edge: nothing on the other side to compare with
    const Eigen::MatrixX3i& F = shape.tree().faces();
    const Eigen::MatrixX3d& V = shape.tree().vertices();
    const int u = F(f, k), v = F(f, (k + 1) % 3);
    double across = 0;
    for (int c = 0; c < 3; ++c)
      if (F(g, c) != u && F(g, c) != v) across = n.dot(to_frame * Eigen::Vector3d(V.row(F(g, c))) - p0);
    return side[third] * across < 0 && std::abs(across) > eps ? 0.5 : 0.0;
  }
  return 1;
}

/// Links segment ends that are the same edge crossing the same triangle into polylines.
std::vector<ContourPolyline> chain(const std::vector<ContourSegment>& segments) {
  using Key = std::tuple<int, int, int, int>;  // edge part, edge vertices, triangle
  const auto key = [](const ContourPoint& p) { return Key{p.edge_part, p.edge[0], p.edge[1], p.triangle}; };
  std::multimap<Key, int> ends;  // key → 2·segment + end
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    for (int e = 0; e < 2; ++e) ends.emplace(key(segments[s].ends[e]), 2 * s + e);
  const auto partner = [&](int end) {  // the other segment's end at the same point, or −1
    const auto [lo, hi] = ends.equal_range(key(segments[end / 2].ends[end % 2]));
    for (auto it = lo; it != hi; ++it)
      if (it->second / 2 != end / 2) return it->second;
    return -1;
  };
  std::vector<bool> used(segments.size(), false);
  std::vector<ContourPolyline> polylines;
  const auto walk = [&](int start_end, ContourPolyline& line) {  // from an end, along the chain
    int end = start_end;
    while (true) {
      const int s = end / 2;
      used[s] = true;
      const int far = end ^ 1;
      line.points.push_back(segments[s].ends[far % 2].position);
      const int next = partner(far);
      if (next < 0) return false;
      if (used[next / 2]) return next == start_end;
      end = next;
    }
  };
  // Open chains first (from an end that has no partner), then the loops that remain.
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < static_cast<int>(segments.size()); ++s) {
      if (used[s]) continue;
      const int start = pass == 0 ? (partner(2 * s) < 0 ? 2 * s : (partner(2 * s + 1) < 0 ? 2 * s + 1 : -1)) : 2 * s;
      if (start < 0) continue;
      ContourPolyline line;
      line.points.push_back(segments[s].ends[start % 2].position);
      line.closed = walk(start, line);
      if (line.closed) line.points.pop_back();  // the loop's last point is its first
      polylines.push_back(std::move(line));
    }
  return polylines;
}

}  // namespace

IntersectionContour intersection_contour(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                                         const Eigen::Isometry3d& place_b, ContourPolylines polylines) {
  const Eigen::Isometry3d b_to_a = place_a.inverse() * place_b;
  const PairContext ctx{a, b, place_a};
  IntersectionContour contour;
  MovedPlanes b_planes(static_cast<int>(b.tree().faces().rows()));
  a.tree().for_each_overlapping_pair(b.tree(), b_to_a, [&](const geometry::TriangleBvh::PlacedPair& pair) {
    const int fa = pair.f, fb = pair.g;
    const Triangle& ta = pair.f_corners;
    const Triangle& tb = pair.g_corners;
    // The exact test below decides the same as these two filters where they are certain, and
    // takes the sides they are certain of.
    const geometry::CertainPlane& plane_a = a.planes[pair.f_position];
    const geometry::KnownSides side_b = geometry::certain_sides(plane_a, tb);
    if (geometry::all_on_one_side(side_b)) return;
    const geometry::CertainPlane& plane_b = b_planes(pair.g_position, tb);
    const geometry::KnownSides side_a = geometry::certain_sides(plane_b, ta);
    if (geometry::all_on_one_side(side_a)) return;
    const geometry::TriangleContact contact =
        geometry::intersect_triangles(ta[0], ta[1], ta[2], tb[0], tb[1], tb[2], side_a, side_b);
    if (!contact.intersect || contact.coplanar || contact.points.size() != 2) return;
    const CrossingPair crossing{fa, fb, ta, tb, plane_a.normal.normalized(), plane_b.normal.normalized()};
    const double weight = edge_weight(ta, fa, a, Eigen::Isometry3d::Identity(), tb[0], crossing.nb) *
                          edge_weight(tb, fb, b, b_to_a, ta[0], crossing.na);
    if (weight == 0) return;
    ContourSegment segment;
    segment.weight = weight;
    segment.triangle_a = fa;
    segment.triangle_b = fb;
    for (int e = 0; e < 2; ++e) segment.ends[e] = contour_point(ctx, contact.points[e], crossing);
    contour.segments.push_back(segment);
  });
  // The tree visits pairs in an order that depends on the traversal only: sort for a stable
  // answer regardless of which part's tree is walked first (by key, then each segment copied
  // once into place: segments are large).
  std::vector<std::pair<std::pair<int, int>, int>> order(contour.segments.size());
  for (std::size_t s = 0; s < order.size(); ++s)
    order[s] = {{contour.segments[s].triangle_a, contour.segments[s].triangle_b}, static_cast<int>(s)};
  std::sort(order.begin(), order.end());
  std::vector<ContourSegment> sorted;
  sorted.reserve(order.size());
  for (const auto& [pair, s] : order) sorted.push_back(contour.segments[s]);
  contour.segments = std::move(sorted);
  for (const ContourSegment& s : contour.segments) contour.length += s.weight * s.length();
  if (polylines == ContourPolylines::kChained) contour.polylines = chain(contour.segments);
  return contour;
}

TwistGradient contour_length_gradient(const IntersectionContour& contour) {
  constexpr double kMinCrossing = 1e-3;  // |n·d| ≥ kMinCrossing |d| (n is unit)
  TwistGradient gradient;
  for (const ContourSegment& segment : contour.segments) {
    const Eigen::Vector3d along = segment.ends[1].position - segment.ends[0].position;
    const double length = along.norm();
    if (length == 0) continue;
    const Eigen::Vector3d tau = segment.weight * along / length;
    for (int e = 0; e < 2; ++e) {
      const ContourPoint& p = segment.ends[e];
      const Eigen::Vector3d s_tau = (e == 0 ? -1.0 : 1.0) * tau;  // ∂‖Ic‖/∂p
      const Eigen::Vector3d& d = p.edge_direction;
      const Eigen::Vector3d& n = p.plane_normal;
      double nd = n.dot(d);
      const double floor = kMinCrossing * d.norm();
      if (std::abs(nd) < floor) nd = nd < 0 ? -floor : floor;
      if (nd == 0) continue;  // a zero-length edge
      // dp = P u(p): P = I − d nᵀ/(n·d) when a owns the edge, d nᵀ/(n·d) when a owns the
      // triangle; the gradient of ‖Ic‖ with respect to u(p) is Pᵀ ∂‖Ic‖/∂p.
      const Eigen::Vector3d slide = n * (d.dot(s_tau) / nd);
      gradient.add_point(p.position, p.edge_part == 0 ? Eigen::Vector3d(s_tau - slide) : slide);
    }
  }
  return gradient;
}

}  // namespace reconfig::resolve
