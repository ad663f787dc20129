#pragma once
/// @file
/// Exact boolean subtraction of closed triangle meshes (the carving step of eq. 4).

#include <string>
#include <vector>

#include "reconfig/common/progress.h"
#include "reconfig/geometry/mesh.h"

namespace reconfig::sweep {

struct SubtractionResult {
  /// `solid` minus every cutter; equal to `solid` when refused.
  geometry::Mesh mesh;
  /// Empty when the subtraction succeeded and its result is a valid solid (closed, manifold,
  /// oriented, outward, no degenerate faces or self-intersections: `geometry::check_mesh`);
  /// otherwise why it was refused, naming the input at fault ("cutter 2: open: ...").
  std::string problem;
  bool cancelled = false;
  bool ok() const { return problem.empty() && !cancelled; }
};

/// solid \ (cutter_1 ∪ … ∪ cutter_n), computed with CGAL's corefinement on exact
/// constructions (Epeck), one cutter after the other; coordinates are rounded to double once at
/// the end, so every triangle of `solid` away from the cuts is kept bit for bit. The inputs must
/// be valid solids and the result must be one, or nothing changes and `problem` says why.
/// @param solid    #V×3, #F×3 closed, outward
/// @param cutters  each #V×3, #F×3 closed, outward
/// @param progress fraction of the cutters done; false cancels
SubtractionResult subtract_meshes(const geometry::Mesh& solid, const std::vector<geometry::Mesh>& cutters,
                                  const ProgressCallback& progress = {});

}  // namespace reconfig::sweep
