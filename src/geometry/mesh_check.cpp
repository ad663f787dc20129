#include "reconfig/geometry/mesh_check.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "geometry/detail/exact_collinear.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/self_intersections.h"

namespace reconfig::geometry {
namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

template <class Element>
void note(MeshFindings<Element>& findings, const Element& element, int max_examples) {
  ++findings.count;
  if (static_cast<int>(findings.examples.size()) < max_examples) findings.examples.push_back(element);
}

/// One use of an undirected edge by a face.
struct HalfEdge {
  int low, high;  ///< vertex indices, low < high
  bool forward;   ///< the face walks low → high
  int face;
  int corner_low, corner_high;  ///< the face corners (0..2) holding `low` and `high`
  auto key() const { return std::tie(low, high, face); }
};

std::string edge_text(const MeshEdge& e) { return std::to_string(e[0]) + "\u2013" + std::to_string(e[1]); }
std::string pair_text(const FacePair& p) { return std::to_string(p[0]) + "\u00d7" + std::to_string(p[1]); }
std::string index_text(int i) { return std::to_string(i); }

/// "1 triangle", "2 triangles".
std::string count_of(int count, const std::string& singular, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

template <class Element, class Format>
std::string describe(const MeshFindings<Element>& findings, const std::string& singular, const std::string& plural,
                     Format format) {
  std::string text = count_of(findings.count, singular, plural);
  if (!findings.examples.empty()) {
    text += " (e.g. ";
    const std::size_t shown = std::min<std::size_t>(findings.examples.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) text += (i ? ", " : "") + format(findings.examples[i]);
    text += ")";
  }
  return text;
}

}  // namespace

bool MeshReport::is_closed() const {
  return face_count > 0 && !out_of_range_faces.any() && !boundary_edges.any();
}
bool MeshReport::is_manifold() const { return !non_manifold_edges.any() && !non_manifold_vertices.any(); }
bool MeshReport::is_oriented() const { return !inconsistent_edges.any(); }
bool MeshReport::is_outward() const { return signed_volume > 0; }
bool MeshReport::is_valid_solid() const {
  return is_closed() && is_manifold() && is_oriented() && is_outward() && !non_finite_vertices.any() &&
         !degenerate_faces.any() && !self_intersections.any();
}

std::string MeshReport::summary() const {
  std::vector<std::string> parts;
  if (face_count == 0) parts.push_back("no triangles");
  if (out_of_range_faces.any()) parts.push_back(describe(out_of_range_faces, "face with out-of-range indices", "faces with out-of-range indices", index_text));
  if (non_finite_vertices.any()) parts.push_back(describe(non_finite_vertices, "vertex with NaN/infinite coordinates", "vertices with NaN/infinite coordinates", index_text));
  if (boundary_edges.any()) parts.push_back("open: " + describe(boundary_edges, "boundary edge", "boundary edges", edge_text));
  if (non_manifold_edges.any()) parts.push_back(describe(non_manifold_edges, "non-manifold edge", "non-manifold edges", edge_text));
  if (non_manifold_vertices.any()) parts.push_back(describe(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices", index_text));
  if (inconsistent_edges.any()) parts.push_back(describe(inconsistent_edges, "inconsistently oriented edge", "inconsistently oriented edges", edge_text));
  if (degenerate_faces.any()) parts.push_back(describe(degenerate_faces, "degenerate triangle", "degenerate triangles", index_text));
  if (self_intersections.any())
    parts.push_back((self_intersections_truncated ? "at least " : "") +
                    describe(self_intersections, "self-intersecting triangle pair", "self-intersecting triangle pairs", pair_text));
  if (face_count > 0 && is_closed() && is_oriented() && !non_finite_vertices.any() && !is_outward())
    parts.push_back(signed_volume < 0 ? "inside out (negative volume)" : "zero volume");
  if (parts.empty()) {
    std::string text = "closed, manifold, " + count_of(face_count, "triangle", "triangles");
    if (component_count > 1) text += ", " + count_of(component_count, "component", "components");
    if (!self_intersections_checked) text += ", self-intersections not checked";
    return text;
  }
  if (face_count > 0) parts.push_back(count_of(face_count, "triangle", "triangles"));
  if (!self_intersections_checked) parts.push_back("self-intersections not checked");
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? "; " : "") + parts[i];
  return text;
}

MeshReport check_mesh(const Mesh& mesh, const MeshCheckOptions& options) {
  const int max_examples = std::max(0, options.max_examples);
  MeshReport report;
  const int n = report.vertex_count = mesh.vertex_count();
  const int m = report.face_count = mesh.face_count();

  std::vector<bool> finite(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v) {
    finite[static_cast<std::size_t>(v)] = mesh.V.row(v).allFinite();
    if (!finite[static_cast<std::size_t>(v)]) note(report.non_finite_vertices, v, max_examples);
  }

  // Per face: indices in range? repeated? collinear?
  std::vector<bool> valid(static_cast<std::size_t>(m)), distinct(static_cast<std::size_t>(m));
  std::vector<bool> referenced(static_cast<std::size_t>(n));
  for (int f = 0; f < m; ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    const bool in_range = a >= 0 && a < n && b >= 0 && b < n && c >= 0 && c < n;
    valid[static_cast<std::size_t>(f)] = in_range;
    if (!in_range) {
      note(report.out_of_range_faces, f, max_examples);
      continue;
    }
    for (int v : {a, b, c}) referenced[static_cast<std::size_t>(v)] = true;
    const bool unique = a != b && b != c && c != a;
    distinct[static_cast<std::size_t>(f)] = unique;
    bool degenerate = !unique;
    if (unique && finite[static_cast<std::size_t>(a)] && finite[static_cast<std::size_t>(b)] &&
        finite[static_cast<std::size_t>(c)])
      degenerate = detail::exactly_collinear(mesh.V.row(a), mesh.V.row(b), mesh.V.row(c));
    if (degenerate) note(report.degenerate_faces, f, max_examples);
  }
  for (int v = 0; v < n; ++v)
    if (!referenced[static_cast<std::size_t>(v)]) note(report.unreferenced_vertices, v, max_examples);

  // Edges: sort the half-edges so the uses of one undirected edge are adjacent.
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * static_cast<std::size_t>(m));
  for (int f = 0; f < m; ++f) {
    if (!valid[static_cast<std::size_t>(f)] || !distinct[static_cast<std::size_t>(f)]) continue;
    for (int k = 0; k < 3; ++k) {
      const int from = mesh.F(f, k), to = mesh.F(f, (k + 1) % 3);
      const int next = (k + 1) % 3;
      if (from < to)
        half_edges.push_back({from, to, true, f, k, next});
      else
        half_edges.push_back({to, from, false, f, next, k});
    }
  }
  std::sort(half_edges.begin(), half_edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return x.key() < y.key(); });

  // Corners (face, k) → 3f + k, joined across shared edges into fans around each vertex.
  UnionFind corners(3 * static_cast<std::size_t>(m));
  std::vector<bool> on_non_manifold_edge(static_cast<std::size_t>(n));
  for (std::size_t begin = 0; begin < half_edges.size();) {
    std::size_t end = begin + 1;
    while (end < half_edges.size() && half_edges[end].low == half_edges[begin].low &&
           half_edges[end].high == half_edges[begin].high)
      ++end;
    const MeshEdge edge{half_edges[begin].low, half_edges[begin].high};
    const std::size_t uses = end - begin;
    if (uses == 1) note(report.boundary_edges, edge, max_examples);
    if (uses > 2) {
      note(report.non_manifold_edges, edge, max_examples);
      on_non_manifold_edge[static_cast<std::size_t>(edge[0])] = true;
      on_non_manifold_edge[static_cast<std::size_t>(edge[1])] = true;
    }
    if (uses == 2 && half_edges[begin].forward == half_edges[begin + 1].forward)
      note(report.inconsistent_edges, edge, max_examples);
    for (std::size_t i = begin + 1; i < end; ++i) {
      const HalfEdge& x = half_edges[begin];
      const HalfEdge& y = half_edges[i];
      corners.unite(3 * static_cast<std::size_t>(x.face) + static_cast<std::size_t>(x.corner_low),
                    3 * static_cast<std::size_t>(y.face) + static_cast<std::size_t>(y.corner_low));
      corners.unite(3 * static_cast<std::size_t>(x.face) + static_cast<std::size_t>(x.corner_high),
                    3 * static_cast<std::size_t>(y.face) + static_cast<std::size_t>(y.corner_high));
    }
    begin = end;
  }

  // A vertex whose corners fall into more than one fan is a pinch.
  {
    std::vector<std::int64_t> fan_of(static_cast<std::size_t>(n), -1);
    std::vector<bool> pinched(static_cast<std::size_t>(n));
    for (int f = 0; f < m; ++f) {
      if (!valid[static_cast<std::size_t>(f)] || !distinct[static_cast<std::size_t>(f)]) continue;
      for (int k = 0; k < 3; ++k) {
        const auto v = static_cast<std::size_t>(mesh.F(f, k));
        const auto fan = static_cast<std::int64_t>(corners.find(3 * static_cast<std::size_t>(f) + static_cast<std::size_t>(k)));
        if (fan_of[v] < 0)
          fan_of[v] = fan;
        else if (fan_of[v] != fan)
          pinched[v] = true;
      }
    }
    for (int v = 0; v < n; ++v)
      if (pinched[static_cast<std::size_t>(v)] && !on_non_manifold_edge[static_cast<std::size_t>(v)])
        note(report.non_manifold_vertices, v, max_examples);
  }

  // Components through shared vertices.
  {
    UnionFind vertices(static_cast<std::size_t>(n));
    for (int f = 0; f < m; ++f) {
      if (!valid[static_cast<std::size_t>(f)]) continue;
      vertices.unite(static_cast<std::size_t>(mesh.F(f, 0)), static_cast<std::size_t>(mesh.F(f, 1)));
      vertices.unite(static_cast<std::size_t>(mesh.F(f, 0)), static_cast<std::size_t>(mesh.F(f, 2)));
    }
    for (int v = 0; v < n; ++v)
      if (referenced[static_cast<std::size_t>(v)] && vertices.find(static_cast<std::size_t>(v)) == static_cast<std::size_t>(v))
        ++report.component_count;
  }

  // Volume and self-intersections over the faces with valid indices.
  Mesh usable;
  const Mesh* checked = &mesh;
  std::vector<int> original_face;  // usable face → face of `mesh`, when some were left out
  if (report.out_of_range_faces.any()) {
    usable.V = mesh.V;
    usable.F.resize(m - report.out_of_range_faces.count, 3);
    for (int f = 0; f < m; ++f)
      if (valid[static_cast<std::size_t>(f)]) {
        usable.F.row(static_cast<int>(original_face.size())) = mesh.F.row(f);
        original_face.push_back(f);
      }
    checked = &usable;
  }
  if (checked->face_count() > 0) report.signed_volume = mass_properties(*checked).volume;

  if (options.check_self_intersections && !report.non_finite_vertices.any()) {
    const SelfIntersections found =
        find_self_intersections(*checked, std::max(0, options.max_self_intersection_pairs), options.progress);
    if (!found.cancelled) {
      report.self_intersections_checked = true;
      report.self_intersections_truncated = found.truncated;
      for (auto [f, g] : found.pairs) {
        if (!original_face.empty()) {
          f = original_face[static_cast<std::size_t>(f)];
          g = original_face[static_cast<std::size_t>(g)];
        }
        note(report.self_intersections, FacePair{f, g}, max_examples);
      }
      if (found.truncated && report.self_intersections.count == 0) report.self_intersections.count = 1;
    }
  }
  return report;
}

}  // namespace reconfig::geometry
