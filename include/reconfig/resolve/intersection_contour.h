#pragma once
/// @file
/// Intersection contours of two placed parts (reconfigurables §6.3, Fig. 14): the curves
/// where their surfaces cross, and the gradient of their length (Volino & Magnenat-Thalmann).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

#include "reconfig/resolve/part_shape.h"
#include "reconfig/resolve/twist_gradient.h"

namespace reconfig::resolve {

/// An end of a contour segment: where an edge of one part crosses a triangle of the other.
struct ContourPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< world
  int edge_part = 0;  ///< 0: the edge is part a's and the triangle part b's; 1: the reverse
  std::array<int, 2> edge{-1, -1};  ///< the edge's vertex indices in its part's mesh, ascending
  int triangle = -1;                ///< the crossed triangle, in the other part's mesh
  /// World, the edge's vector as its triangle runs (F(f, k) → F(f, k + 1); `edge` is sorted).
  Eigen::Vector3d edge_direction = Eigen::Vector3d::Zero();
  Eigen::Vector3d plane_normal = Eigen::Vector3d::Zero();    ///< world, unit normal of the triangle
};

/// The piece of contour two triangles share (their intersection segment).
struct ContourSegment {
  std::array<ContourPoint, 2> ends;
  int triangle_a = -1, triangle_b = -1;
  /// How much of the segment is a crossing of the surfaces: 1 in general position. A segment
  /// along an edge that lies in the other triangle's plane is found from both faces of that
  /// edge: each counts ½ when those faces lie on opposite sides of the plane (the surface
  /// crosses there), 0 when they do not (surfaces that only touch along the edge, as boxes
  /// resting face to face do, have no contour). Along edges of both parts: ¼ per pair.
  double weight = 1;
  double length() const { return (ends[1].position - ends[0].position).norm(); }
};

/// A chain of segments: consecutive points, `closed` when it comes back to its start.
struct ContourPolyline {
  std::vector<Eigen::Vector3d> points;
  bool closed = false;
};

struct IntersectionContour {
  /// Every transversal triangle pair's segment of non-zero weight. Pairs that only touch at a
  /// point, or lie in one plane (their overlap is an area, not a curve), contribute none:
  /// coplanar overlap is measured by the penetration term instead (`penetration.h`).
  std::vector<ContourSegment> segments;
  /// The segments chained through their shared ends (an end is the same point of two segments
  /// when it is the same edge crossing the same triangle): closed loops where both meshes are
  /// closed and in general position; open chains where degenerate contact breaks the links.
  std::vector<ContourPolyline> polylines;
  double length = 0;  ///< ‖Ic‖: the sum of the segments' lengths times their weights
};

/// Whether `intersection_contour` chains its segments into polylines (the energy needs only the
/// segments: chaining is for showing the curves).
enum class ContourPolylines { kChained, kNone };

/// The intersection contour of part a placed by `place_a` and part b placed by `place_b`
/// (rigid maps from each part's rest frame to the world). Triangle pairs are found through the
/// rest-frame trees; each pair's crossing is decided exactly (`geometry::intersect_triangles`).
IntersectionContour intersection_contour(const PartShape& a, const Eigen::Isometry3d& place_a, const PartShape& b,
                                         const Eigen::Isometry3d& place_b,
                                         ContourPolylines polylines = ContourPolylines::kChained);

/// ∂‖Ic‖/∂(rigid motion of part a), part b held still. Each end p of a segment slides along
/// its edge as the parts move: dp = u_e(p) + d (n·(u_t(p) − u_e(p)))/(n·d) for the edge vector
/// d, the triangle normal n and the velocities u_e, u_t of the edge's and the triangle's parts.
/// Where an edge runs nearly parallel to the triangle it crosses the slide is unbounded;
/// |n·d| is clamped to at least 1/1000 of |d| there (edges within 0.06° of the plane).
/// Moving part b by (v, ω) changes ‖Ic‖ as moving a by (−v, −ω) does: the gradient for b is
/// the negative of this one.
TwistGradient contour_length_gradient(const IntersectionContour& contour);

}  // namespace reconfig::resolve
