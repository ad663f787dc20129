#pragma once
/// @file
/// What a designer needs to know before trusting a part's mesh: is it a valid solid, and if
/// not, where is it broken.

#include <array>
#include <string>
#include <vector>

#include "reconfig/common/progress.h"
#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// One kind of problem: how many elements have it, and the first few (in index order).
template <class Element>
struct MeshFindings {
  int count = 0;                   ///< number of elements with the problem
  std::vector<Element> examples;   ///< at most `MeshCheckOptions::max_examples` of them
  bool any() const { return count > 0; }
};

/// An undirected edge as its two vertex indices, the lower first.
using MeshEdge = std::array<int, 2>;
/// Two face indices, the lower first.
using FacePair = std::array<int, 2>;

/// How thoroughly `check_mesh` looks.
struct MeshCheckOptions {
  /// Look for triangles that intersect improperly (the costly part: a BVH traversal with exact
  /// triangle–triangle tests). When false, `MeshReport::self_intersections_checked` is false.
  bool check_self_intersections = true;
  /// Stop looking for self-intersections after this many pairs (`MeshReport::self_intersections`
  /// then counts only these and `self_intersections_truncated` is set). With 0 the search stops
  /// at the first pair found, and the report only tells whether there is any.
  int max_self_intersection_pairs = 10000;
  /// How many example elements each finding keeps.
  int max_examples = 5;
  /// Progress of the self-intersection search, which can be cancelled (the report then says
  /// `self_intersections_checked == false`).
  ProgressCallback progress;
};

/// The result of `check_mesh`. Faces with an out-of-range index are left out of every other
/// check; faces with a repeated index are left out of the edge checks (both are reported).
struct MeshReport {
  int vertex_count = 0;  ///< #V
  int face_count = 0;    ///< #F

  /// Faces with an index outside [0, #V).
  MeshFindings<int> out_of_range_faces;
  /// Vertices with a NaN or infinite coordinate.
  MeshFindings<int> non_finite_vertices;
  /// Faces with zero area: a repeated index, or three exactly collinear corners (exact predicate).
  MeshFindings<int> degenerate_faces;
  /// Vertices no face uses (harmless, but often a sign of a botched export).
  MeshFindings<int> unreferenced_vertices;
  /// Edges used by a single face: holes. A closed mesh has none.
  MeshFindings<MeshEdge> boundary_edges;
  /// Edges shared by more than two faces.
  MeshFindings<MeshEdge> non_manifold_edges;
  /// Vertices where several fans of faces meet only at the vertex (a pinch, as two cones tip to
  /// tip), not counting vertices of non-manifold edges.
  MeshFindings<int> non_manifold_vertices;
  /// Edges shared by two faces that both use it in the same direction: the faces disagree on
  /// which side is out.
  MeshFindings<MeshEdge> inconsistent_edges;
  /// Pairs of faces that intersect improperly (more than the edge or vertex they share), as
  /// found by `find_self_intersections`. Empty when not checked (coordinates not finite, check
  /// skipped or cancelled).
  MeshFindings<FacePair> self_intersections;
  bool self_intersections_checked = false;
  /// More pairs exist than `MeshCheckOptions::max_self_intersection_pairs`: the count is a
  /// lower bound.
  bool self_intersections_truncated = false;

  /// Connected components (faces joined through shared vertices).
  int component_count = 0;
  /// Signed enclosed volume (see `mass_properties`), over the faces with valid indices.
  double signed_volume = 0;

  /// Has faces, all indices in range, and no boundary edges.
  bool is_closed() const;
  /// No non-manifold edges or vertices.
  bool is_manifold() const;
  /// Neighbouring faces agree on orientation.
  bool is_oriented() const;
  /// The enclosed volume is positive (faces point out).
  bool is_outward() const;
  /// Closed, manifold, oriented, outward, all coordinates finite, no degenerate faces, no
  /// self-intersections. If the self-intersection check was skipped this does not know about
  /// them and trusts that there are none (`summary` says so).
  bool is_valid_solid() const;
  /// One line for a log or status bar: "closed, manifold, 1234 triangles" for a valid solid,
  /// otherwise the problems with a few examples, such as
  /// "open: 12 boundary edges (e.g. 3–17, 4–18); 1234 triangles".
  std::string summary() const;
};

/// Checks `mesh` for everything that keeps it from being a valid solid. Never throws on bad
/// data and never crashes: any V and F (out-of-range or negative indices, NaN coordinates,
/// no faces) give a report.
/// @param mesh     #V×3 positions, #F×3 triangles
/// @param options  what to check
MeshReport check_mesh(const Mesh& mesh, const MeshCheckOptions& options = {});

}  // namespace reconfig::geometry
