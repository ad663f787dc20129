#pragma once
/// @file
/// Exact static triangle–triangle intersection.

#include <Eigen/Core>
#include <array>
#include <vector>

namespace reconfig::geometry {

/// The points two triangles share.
struct TriangleContact {
  bool intersect = false;  ///< the closed triangles share at least one point (exact)
  bool coplanar = false;   ///< both lie in one plane (exact); `points` is then a polygon
  /// What they share: nothing (no contact), one point (touching at a point), the two ends of
  /// the intersection segment, or (coplanar) the vertices of the convex overlap polygon
  /// (up to 6, in order around it, no repeats). Coordinates are rounded to double; the
  /// decision `intersect` and the number of points are exact. Transversal triangles in
  /// general position are constructed in doubles under error bounds; every other case
  /// (touching, coplanar, degenerate, or when the bounds cannot decide) exactly (CGAL Epeck).
  std::vector<Eigen::Vector3d> points;
};

/// Whether two closed triangles share a point, decided exactly (filtered exact predicates:
/// never fooled by rounding), including coplanar, touching and degenerate triangles
/// (a degenerate triangle is treated as the segment or point it collapses to). A triangle with
/// a NaN or infinite coordinate intersects nothing. Cheap when the triangles' boxes are
/// disjoint (a few comparisons), filtered exact orientation tests otherwise.
bool triangles_intersect(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                         const Eigen::Vector3d& b0, const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

/// Same decision as `triangles_intersect`, plus the shared points. Non-finite coordinates give
/// no contact.
TriangleContact intersect_triangles(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                    const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                                    const Eigen::Vector3d& b1, const Eigen::Vector3d& b2);

/// The exact sides (−1, +1) of a triangle's corners with respect to another's plane, as far as
/// a caller has already decided them; 0: not decided. The side of corner q with respect to the
/// plane of (p0, p1, p2) is the sign of ((p1 − p0) × (p2 − p0)) · (q − p0), evaluated exactly.
using KnownSides = std::array<int, 3>;

/// `intersect_triangles` for a caller that knows some of the corners' exact sides already (a
/// filter such as `certain_plane.h`): `side_a` those of a's corners with respect to b's plane,
/// `side_b` those of b's with respect to a's. The sides left 0 are decided here; the answer is
/// the one `intersect_triangles` gives. A side given wrongly gives an undefined answer.
TriangleContact intersect_triangles(const Eigen::Vector3d& a0, const Eigen::Vector3d& a1,
                                    const Eigen::Vector3d& a2, const Eigen::Vector3d& b0,
                                    const Eigen::Vector3d& b1, const Eigen::Vector3d& b2, const KnownSides& side_a,
                                    const KnownSides& side_b);

}  // namespace reconfig::geometry
