#include "reconfig/sculpt/remesh_in_box.h"

#include "sculpt/detail/remesh.h"
#include "sculpt/detail/sort_unique.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace reconfig::sculpt {
namespace {

constexpr int kMaxPasses = 8;

/// The part of the mesh that may change: the faces with a vertex in the box (local face
/// numbers in the order of the mesh's, then the new faces), the vertices by their index in the
/// mesh (new ones numbered after its last), so a remesh costs little beyond the box.
struct Work {
  SculptMesh& mesh;
  int original_vertices = 0;
  std::vector<Eigen::Vector3d> new_V = {}, new_N = {};
  std::vector<std::array<int, 3>> F = {};  ///< a removed face has F[f][0] = −1
  std::vector<int> original_face = {};     ///< per local face of the mesh's, its index there
  std::vector<char> in_box = {};           ///< per vertex
  /// The faces a split pass looks at: those the pass before split, or where it left long edges
  /// (the others were looked at and did not change); none yet: every face.
  std::optional<std::vector<int>> candidates = {};
  /// The short edges the first split pass found (in `ShortEdges` order), if it was asked to
  /// look: splits neither move vertices nor remove short edges, so after them the short edges
  /// are these and those of the new vertices.
  std::optional<std::vector<std::pair<double, std::pair<int, int>>>> first_short_edges = {};
  bool normals = false;
  /// The first position and normal of each vertex of the mesh's that was set (for the undo log).
  std::unordered_map<int, std::pair<Eigen::Vector3d, Eigen::Vector3d>> first_values = {};

  void remember(int v) {
    if (v < original_vertices && !first_values.count(v)) first_values.emplace(v, std::pair(position(v), normal(v)));
  }

  Eigen::Vector3d position(int v) const {
    return v < original_vertices ? Eigen::Vector3d(mesh.V().row(v)) : new_V[v - original_vertices];
  }
  Eigen::Vector3d normal(int v) const {
    if (!normals) return Eigen::Vector3d::Zero();
    return v < original_vertices ? Eigen::Vector3d(mesh.N().row(v)) : new_N[v - original_vertices];
  }
  void set_position(int v, const Eigen::Vector3d& p) {
    remember(v);
    if (v < original_vertices) mesh.V().row(v) = p.transpose();
    else new_V[v - original_vertices] = p;
  }
  void set_normal(int v, const Eigen::Vector3d& n) {
    if (!normals) return;
    remember(v);
    if (v < original_vertices) mesh.N().row(v) = n.transpose();
    else new_N[v - original_vertices] = n;
  }
  int vertex_count() const { return original_vertices + static_cast<int>(new_V.size()); }
  double length(int a, int b) const { return (position(a) - position(b)).norm(); }
  double squared_length(int a, int b) const { return (position(a) - position(b)).squaredNorm(); }
  int add_vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, bool inside) {
    new_V.push_back(p);
    new_N.push_back(n);
    in_box.push_back(inside);
    return vertex_count() - 1;
  }
};

using Edge = std::pair<int, int>;
Edge edge(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// The corner after corner i of a triangle.
constexpr int kNext[3] = {1, 2, 0};

/// A face's corners: where they are and whether they are in the box, looked up once.
struct Corners {
  Corners(const Work& work, const std::array<int, 3>& t)
      : position{work.position(t[0]), work.position(t[1]), work.position(t[2])},
        inside{work.in_box[t[0]] != 0, work.in_box[t[1]] != 0, work.in_box[t[2]] != 0} {}
  /// The same value as `Work::squared_length` of the corners' vertices.
  double squared_length(int i, int j) const { return (position[i] - position[j]).squaredNorm(); }

  Eigen::Vector3d position[3];
  bool inside[3];
};

/// One side of an edge (the edge and one of its faces): sorted by edge, the two faces of an edge
/// of a closed manifold come next to each other.
struct EdgeSide {
  Edge edge;
  int face = 0;
  bool operator<(const EdgeSide& other) const { return edge < other.edge || (edge == other.edge && face < other.face); }
};

/// The sides of the edges longer than `max_edge` with an endpoint in the box, on the candidate
/// faces. A long edge has both its faces there (the pass before split it or left it long).
/// Adds the short edges of face t, each from the face where it runs from its lower vertex to
/// its higher one (so once), with both ends in the box and `keep(a, b)`, to `short_edges`.
template <typename Keep>
void add_short_edges(const std::array<int, 3>& t, const Corners& corners, double min_edge, Keep keep,
                     std::vector<std::pair<double, Edge>>& short_edges) {
  for (int i = 0; i < 3; ++i) {
    const int j = kNext[i], a = t[i], b = t[j];
    if (a < b && corners.inside[i] && corners.inside[j] && corners.squared_length(i, j) < min_edge * min_edge &&
        keep(a, b))
      short_edges.push_back({std::sqrt(corners.squared_length(i, j)), {a, b}});
  }
}

/// @param min_edge  > 0 on the first pass (every face looked at): its short edges are kept in
///   `work.first_short_edges` for the collapse pass
std::vector<EdgeSide> long_edge_sides(Work& work, double max_edge, double min_edge) {
  std::vector<EdgeSide> sides;
  const double max_squared = max_edge * max_edge;
  const bool collect = !work.candidates && min_edge > 0;
  if (collect) work.first_short_edges.emplace();
  const int count = work.candidates ? static_cast<int>(work.candidates->size()) : static_cast<int>(work.F.size());
  for (int k = 0; k < count; ++k) {
    const int f = work.candidates ? (*work.candidates)[k] : k;
    const auto& t = work.F[f];
    if (t[0] < 0) continue;
    const Corners corners(work, t);
    for (int i = 0; i < 3; ++i) {
      const int j = kNext[i];
      if ((corners.inside[i] || corners.inside[j]) && corners.squared_length(i, j) > max_squared)
        sides.push_back({edge(t[i], t[j]), f});
    }
    if (collect) add_short_edges(t, corners, min_edge, [](int, int) { return true; }, *work.first_short_edges);
  }
  std::sort(sides.begin(), sides.end());
  return sides;
}

/// Replaces face f = (x, y, c) with its edge x→y split at m by (x, m, c) and (m, y, c).
void split_face(Work& work, int f, int a, int b, int m) {
  auto t = work.F[f];
  int i = 0;
  while (!((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a))) ++i;
  const int x = t[i], y = t[(i + 1) % 3], c = t[(i + 2) % 3];
  work.F[f] = {x, m, c};
  work.F.push_back({m, y, c});
}

struct LongEdge {
  double length = 0;
  Edge edge;
  int faces[2] = {0, 0};
};

int split_pass(Work& work, const Eigen::AlignedBox3d& box, double max_edge, double min_edge) {
  const std::vector<EdgeSide> sides = long_edge_sides(work, max_edge, min_edge);
  std::vector<LongEdge> long_edges;
  for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
    const Edge e = sides[i].edge;
    if (sides[i + 1].edge != e || (i + 2 < sides.size() && sides[i + 2].edge == e)) continue;  // two faces only
    long_edges.push_back({work.length(e.first, e.second), e, {sides[i].face, sides[i + 1].face}});
    ++i;
  }
  std::sort(long_edges.begin(), long_edges.end(), [](const LongEdge& x, const LongEdge& y) {
    return x.length > y.length || (x.length == y.length && x.edge < y.edge);
  });
  std::vector<char> used(work.F.size(), 0);
  std::vector<int> next;  // the next pass's candidates: the faces split, or of edges left long
  int splits = 0;
  for (const LongEdge& long_edge : long_edges) {
    const auto [a, b] = long_edge.edge;
    next.insert(next.end(), {long_edge.faces[0], long_edge.faces[1]});
    if (used[long_edge.faces[0]] || used[long_edge.faces[1]]) continue;
    used[long_edge.faces[0]] = used[long_edge.faces[1]] = 1;
    Eigen::Vector3d n = work.normal(a) + work.normal(b);
    if (n.norm() > 0) n.normalize();
    const Eigen::Vector3d p = (work.position(a) + work.position(b)) / 2;
    const int m = work.add_vertex(p, n, box.contains(p));
    split_face(work, long_edge.faces[0], a, b, m);
    split_face(work, long_edge.faces[1], a, b, m);
    next.insert(next.end(), {static_cast<int>(work.F.size()) - 2, static_cast<int>(work.F.size()) - 1});
    ++splits;
  }
  detail::sort_unique(next, static_cast<int>(work.F.size()));
  work.candidates = std::move(next);
  return splits;
}

Eigen::Vector3d face_normal(const Work& work, const std::array<int, 3>& t) {
  return (work.position(t[1]) - work.position(t[0])).cross(work.position(t[2]) - work.position(t[0]));
}

using VertexFaces = std::unordered_map<int, std::vector<int>>;

/// Collapses b into a (moved to the midpoint) if it keeps the mesh a manifold and no face turns over.
bool try_collapse(Work& work, VertexFaces& vertex_faces, int a, int b, double max_edge) {
  std::set<int> around_a, around_b;
  for (int f : vertex_faces[a]) around_a.insert(work.F[f].begin(), work.F[f].end());
  for (int f : vertex_faces[b]) around_b.insert(work.F[f].begin(), work.F[f].end());
  std::vector<int> shared;
  for (int v : around_a)
    if (v != a && v != b && around_b.count(v)) shared.push_back(v);
  if (shared.size() != 2 || around_a.size() <= 4 || around_b.size() <= 4) return false;  // link condition, no tetrahedra
  const Eigen::Vector3d m = (work.position(a) + work.position(b)) / 2;
  for (int v : {a, b})
    for (int f : vertex_faces[v]) {
      const auto& t = work.F[f];
      if (std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) continue;  // removed
      const Eigen::Vector3d before = face_normal(work, t);
      const Eigen::Vector3d saved = work.position(v);
      work.set_position(v, m);
      const Eigen::Vector3d after = face_normal(work, t);
      work.set_position(v, saved);
      if (!(after.dot(before) > 0.2 * before.norm() * after.norm())) return false;
      for (int w : t)
        if (w != v && (work.position(w) - m).norm() > max_edge) return false;
    }
  work.set_position(a, m);
  const Eigen::Vector3d n = work.normal(a) + work.normal(b);
  if (n.norm() > 0) work.set_normal(a, n.normalized());
  for (int f : vertex_faces[a]) {
    auto& t = work.F[f];
    if (std::count(t.begin(), t.end(), b)) t[0] = -1;
  }
  for (int f : vertex_faces[b])
    if (work.F[f][0] >= 0)
      for (int& w : work.F[f])
        if (w == b) w = a;
  return true;
}

/// The edges shorter than `min_edge` with both ends in the box: those the first split pass
/// found and those of the vertices splits added (once only), or else a scan of every face.
std::vector<std::pair<double, Edge>> short_edges_now(Work& work, double min_edge) {
  const bool known = work.first_short_edges.has_value();
  std::vector<std::pair<double, Edge>> short_edges;
  if (known) short_edges = std::move(*work.first_short_edges);
  work.first_short_edges.reset();
  const int added = work.original_vertices;  // vertices from this number on are new
  for (const auto& t : work.F) {
    if (known && t[0] < added && t[1] < added && t[2] < added) continue;
    if (t[0] < 0 || work.in_box[t[0]] + work.in_box[t[1]] + work.in_box[t[2]] < 2) continue;
    const Corners corners(work, t);
    if (known) add_short_edges(t, corners, min_edge, [added](int a, int b) { return a >= added || b >= added; }, short_edges);
    else add_short_edges(t, corners, min_edge, [](int, int) { return true; }, short_edges);
  }
  return short_edges;
}

int collapse_pass(Work& work, double min_edge, double max_edge) {
  std::vector<std::pair<double, Edge>> short_edges = short_edges_now(work, min_edge);
  if (short_edges.empty()) return 0;
  std::sort(short_edges.begin(), short_edges.end());
  VertexFaces vertex_faces;  // of the vertices in the box only
  for (int f = 0; f < static_cast<int>(work.F.size()); ++f)
    if (work.F[f][0] >= 0)
      for (int v : work.F[f])
        if (work.in_box[v]) vertex_faces[v].push_back(f);
  std::vector<char> locked(work.vertex_count(), 0);
  int collapses = 0;
  for (const auto& [length, e] : short_edges) {
    const auto [a, b] = e;
    if (locked[a] || locked[b]) continue;
    if (!try_collapse(work, vertex_faces, a, b, max_edge)) continue;
    ++collapses;
    for (int v : {a, b})
      for (int f : vertex_faces[v])
        for (int w : work.F[f])
          if (w >= 0) locked[w] = 1;
    locked[a] = locked[b] = 1;
  }
  return collapses;
}

}  // namespace

namespace {

/// Puts the work back into the mesh: the changed faces in place and the new ones after them;
/// the faces collapses removed stay (their numbers go to `changes`) for `compact` to drop.
void write_back(const Work& work, SculptMesh& mesh, detail::RemeshChanges& changes) {
  const int old_faces = mesh.face_count(), added = static_cast<int>(work.F.size() - work.original_face.size());
  for (const auto& [v, values] : work.first_values) {
    changes.moved.push_back(v);
    changes.moved_from.push_back(values.first);
    changes.moved_normal_from.push_back(values.second);
  }
  mesh.resize(work.vertex_count(), old_faces + added);
  auto V = mesh.V();
  auto N = mesh.N();
  auto F = mesh.F();
  for (std::size_t i = 0; i < work.new_V.size(); ++i) {
    V.row(work.original_vertices + i) = work.new_V[i].transpose();
    if (work.normals) N.row(work.original_vertices + i) = work.new_N[i].transpose();
  }
  for (std::size_t f = 0; f < work.F.size(); ++f) {
    const bool appended = f >= work.original_face.size();
    const int target = appended ? old_faces + int(f - work.original_face.size()) : work.original_face[f];
    const std::array<int, 3> before =
        appended ? std::array{-1, -1, -1} : std::array{F(target, 0), F(target, 1), F(target, 2)};
    if (before == work.F[f]) continue;
    changes.before.push_back(before);
    changes.faces.push_back(target);
    if (work.F[f][0] < 0) {
      changes.removed_faces.push_back(target);
      if (appended) F.row(target) = F.row(work.original_face.front());  // a valid row until compacted
    } else {
      F.row(target) << work.F[f][0], work.F[f][1], work.F[f][2];
    }
  }
}

}  // namespace

namespace detail {

void compact(const std::vector<int>& removed_faces, SculptMesh& mesh) {
  if (removed_faces.empty()) return;
  const bool normals = mesh.has_normals();
  auto V = mesh.V();
  auto N = mesh.N();
  auto F = mesh.F();
  std::vector<char> removed(mesh.face_count(), 0);
  for (int f : removed_faces) removed[f] = 1;
  std::vector<int> index(mesh.vertex_count(), -1);
  int faces = 0;
  for (int f = 0; f < mesh.face_count(); ++f)
    if (!removed[f]) {
      F.row(faces++) = F.row(f);
      for (int c = 0; c < 3; ++c) index[F(f, c)] = 0;
    }
  int vertices = 0;
  for (int v = 0; v < mesh.vertex_count(); ++v)
    if (index[v] == 0) {
      index[v] = vertices;
      V.row(vertices) = V.row(v);
      if (normals) N.row(vertices) = N.row(v);
      ++vertices;
    }
  for (int f = 0; f < faces; ++f)
    for (int c = 0; c < 3; ++c) F(f, c) = index[F(f, c)];
  mesh.resize(vertices, faces);
}

RemeshResult remesh(const Eigen::AlignedBox3d& box, const RemeshOptions& options, const MeshIndex* index,
                    SculptMesh& mesh, RemeshChanges& changes) {
  RemeshResult result;
  changes = {mesh.vertex_count(), mesh.face_count()};
  if (!(options.max_edge > 0)) return result;
  Work work{mesh, mesh.vertex_count()};
  work.normals = mesh.has_normals();
  const auto V = mesh.V();
  const auto F = mesh.F();
  work.in_box.resize(mesh.vertex_count());
  std::vector<int> faces;
  if (index) {
    const std::vector<int> inside = index->vertices_in(box, V);
    faces.reserve(2 * inside.size() + 64);  // a closed surface has about two faces per vertex
    for (int v : inside) work.in_box[v] = 1;
    for (int v : inside)  // each face once: from its first corner in the box
      for (int f : index->faces_of(v)) {
        int first = 0;
        while (!work.in_box[F(f, first)]) ++first;
        if (F(f, first) == v) faces.push_back(f);
      }
    detail::sort_unique(faces, mesh.face_count());
  } else {
    for (int i = 0; i < mesh.vertex_count(); ++i) work.in_box[i] = box.contains(Eigen::Vector3d(V.row(i)));
    for (int f = 0; f < mesh.face_count(); ++f)
      if (work.in_box[F(f, 0)] || work.in_box[F(f, 1)] || work.in_box[F(f, 2)]) faces.push_back(f);
  }
  work.F.reserve(faces.size() + faces.size() / 8);
  work.original_face.reserve(faces.size());
  for (int f : faces) {
    work.F.push_back({F(f, 0), F(f, 1), F(f, 2)});
    work.original_face.push_back(f);
  }
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const int splits = split_pass(work, box, options.max_edge, options.min_edge);
    result.splits += splits;
    if (splits == 0) break;
  }
  for (int pass = 0; pass < kMaxPasses && options.min_edge > 0; ++pass) {
    const int collapses = collapse_pass(work, options.min_edge, options.max_edge);
    result.collapses += collapses;
    if (collapses == 0) break;
  }
  if (result.splits > 0 || result.collapses > 0) write_back(work, mesh, changes);
  return result;
}

}  // namespace detail

RemeshResult remesh_in_box(const Eigen::AlignedBox3d& box, const RemeshOptions& options, geometry::Mesh& mesh,
                           Eigen::MatrixX3d& N) {
  MeshIndex no_index;
  SculptMesh work = SculptMesh::adopt(std::move(mesh), std::move(N), std::move(no_index));
  detail::RemeshChanges changes;
  const RemeshResult result = detail::remesh(box, options, nullptr, work, changes);
  detail::compact(changes.removed_faces, work);
  work.release(mesh, N, no_index);
  return result;
}

}  // namespace reconfig::sculpt
