#pragma once
/// @file
/// What the narrow phase reports: two triangles of two parts intersecting over a time span.

#include <Eigen/Geometry>

namespace reconfig::collision {

/// Triangle `triangle_a` of part `part_a` and `triangle_b` of part `part_b` (part_a < part_b)
/// intersect at every time of [t0, t1] (closed; t0 == t1 for an instant), as the parts'
/// spacetime proxies move. The detector clips contacts to frames (`FrameGrid`): [t0, t1]
/// lies within one frame.
struct TriangleContact {
  int part_a = 0, triangle_a = 0;
  int part_b = 0, triangle_b = 0;
  double t0 = 0, t1 = 0;
  /// Conservative box of where the two triangles meet during [t0, t1]: the intersection of
  /// the boxes they sweep over it, or, where the narrow phase reported [t0, t1] in pieces, the
  /// union of those over each piece.
  Eigen::AlignedBox3d box;
  /// Conservative mode only: the proxies do not intersect here, but the true motion (within
  /// the proxy tolerance of them) may.
  bool possible = false;
  /// The proxy time step (of the pair's merged samples) in which the narrow phase found it.
  double step_t0 = 0, step_t1 = 0;
};

/// Part `inner` lies entirely inside part `outer` (no surface crossing) during [t0, t1].
struct Containment {
  int inner = 0, outer = 0;
  double t0 = 0, t1 = 0;
  Eigen::AlignedBox3d box;  ///< box of the inner part over [t0, t1]
};

}  // namespace reconfig::collision
