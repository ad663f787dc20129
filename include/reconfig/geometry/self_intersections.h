#pragma once
/// @file
/// Pairs of triangles of one mesh that intersect other than through the vertices and edges
/// they share (exact).

#include <utility>
#include <vector>

#include "reconfig/common/progress.h"
#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// The improperly intersecting face pairs of a mesh.
struct SelfIntersections {
  /// Face pairs (f, g) with f < g, sorted lexicographically. When `truncated`, these are the
  /// `max_pairs` lexicographically smallest pairs (deterministic, independent of threads).
  std::vector<std::pair<int, int>> pairs;
  bool truncated = false;  ///< more improper pairs exist than the `max_pairs` returned
  bool cancelled = false;  ///< the progress callback asked to stop; `pairs` is incomplete
};

/// Finds the pairs of faces of `mesh` that intersect improperly, decided exactly:
/// - faces sharing no vertex index: improper if the closed triangles share any point;
/// - faces sharing exactly one vertex index v: improper if they share any point other than v;
/// - faces sharing an edge (two vertex indices u, v): improper if they share any point outside
///   the segment uv, i.e. they are coplanar with their third corners on the same side of uv
///   (folded onto each other), or (zero-area faces) both extend past the same end of uv;
/// - faces with the same three vertex indices (duplicate faces): improper unless zero-area.
///
/// Sharing is by vertex *index*: the mesh is expected to be welded. Two distinct vertices at
/// the same position count as an intersection of the faces using them. Zero-area faces are
/// treated as the segment or point they collapse to.
/// Parallel (TBB) over faces; the result is deterministic.
///
/// @param mesh       #V×3 vertices, #F×3 faces
/// @param max_pairs  at most this many pairs are returned (≥ 0); with 0 only `truncated`
///                   tells whether any improper pair exists (the search stops soon after the
///                   first one found)
/// @param progress   optional progress/cancel callback (fraction of faces processed)
/// @throws InputError (location `face <f>`) if a face indexes a missing vertex or a vertex
///         it uses has a non-finite coordinate
SelfIntersections find_self_intersections(const Mesh& mesh, int max_pairs = 1000,
                                          const ProgressCallback& progress = {});

/// Whether faces f and g of `mesh` intersect improperly, by the rules of
/// `find_self_intersections` (f == g is never improper).
/// @param mesh  #V×3 vertices, #F×3 faces (indices assumed valid)
/// @param f, g  face indices in [0, #F)
bool faces_intersect_improperly(const Mesh& mesh, int f, int g);

}  // namespace reconfig::geometry
