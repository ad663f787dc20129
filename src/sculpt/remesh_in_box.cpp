#include "reconfig/sculpt/remesh_in_box.h"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

namespace reconfig::sculpt {
namespace {

constexpr int kMaxPasses = 8;

/// The working copy: growable vertex and face lists.
struct Work {
  std::vector<Eigen::Vector3d> V, N;
  std::vector<std::array<int, 3>> F;  ///< a removed face has F[f][0] = −1
  std::vector<char> in_box;           ///< per vertex
  bool normals = false;

  double length(int a, int b) const { return (V[a] - V[b]).norm(); }
  int add_vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, bool inside) {
    V.push_back(p);
    N.push_back(n);
    in_box.push_back(inside);
    return static_cast<int>(V.size()) - 1;
  }
};

using Edge = std::pair<int, int>;
Edge edge(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// One side of an edge (the edge and one of its faces): sorted by edge, the two faces of an edge
/// of a closed manifold come next to each other.
struct EdgeSide {
  Edge edge;
  int face = 0;
  bool operator<(const EdgeSide& other) const { return edge < other.edge || (edge == other.edge && face < other.face); }
};

/// The sides of the edges longer than `max_edge` with an endpoint in the box.
std::vector<EdgeSide> long_edge_sides(const Work& work, double max_edge) {
  std::vector<EdgeSide> sides;
  for (int f = 0; f < static_cast<int>(work.F.size()); ++f) {
    const auto& t = work.F[f];
    if (t[0] < 0) continue;
    for (int i = 0; i < 3; ++i) {
      const Edge e = edge(t[i], t[(i + 1) % 3]);
      if ((work.in_box[e.first] || work.in_box[e.second]) && work.length(e.first, e.second) > max_edge)
        sides.push_back({e, f});
    }
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

int split_pass(Work& work, const Eigen::AlignedBox3d& box, double max_edge) {
  const std::vector<EdgeSide> sides = long_edge_sides(work, max_edge);
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
  int splits = 0;
  for (const LongEdge& long_edge : long_edges) {
    if (used[long_edge.faces[0]] || used[long_edge.faces[1]]) continue;
    used[long_edge.faces[0]] = used[long_edge.faces[1]] = 1;
    const auto [a, b] = long_edge.edge;
    Eigen::Vector3d n = work.N[a] + work.N[b];
    if (n.norm() > 0) n.normalize();
    const Eigen::Vector3d p = (work.V[a] + work.V[b]) / 2;
    const int m = work.add_vertex(p, n, box.contains(p));
    split_face(work, long_edge.faces[0], a, b, m);
    split_face(work, long_edge.faces[1], a, b, m);
    ++splits;
  }
  return splits;
}

Eigen::Vector3d face_normal(const Work& work, const std::array<int, 3>& t) {
  return (work.V[t[1]] - work.V[t[0]]).cross(work.V[t[2]] - work.V[t[0]]);
}

/// Collapses b into a (moved to the midpoint) if it keeps the mesh a manifold and no face turns over.
bool try_collapse(Work& work, const std::vector<std::vector<int>>& vertex_faces, int a, int b, double max_edge) {
  std::set<int> around_a, around_b;
  for (int f : vertex_faces[a]) around_a.insert(work.F[f].begin(), work.F[f].end());
  for (int f : vertex_faces[b]) around_b.insert(work.F[f].begin(), work.F[f].end());
  std::vector<int> shared;
  for (int v : around_a)
    if (v != a && v != b && around_b.count(v)) shared.push_back(v);
  if (shared.size() != 2 || around_a.size() <= 4 || around_b.size() <= 4) return false;  // link condition, no tetrahedra
  const Eigen::Vector3d m = (work.V[a] + work.V[b]) / 2;
  for (int v : {a, b})
    for (int f : vertex_faces[v]) {
      const auto& t = work.F[f];
      if (std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) continue;  // removed
      const Eigen::Vector3d before = face_normal(work, t);
      const Eigen::Vector3d saved = work.V[v];
      work.V[v] = m;
      const Eigen::Vector3d after = face_normal(work, t);
      work.V[v] = saved;
      if (!(after.dot(before) > 0.2 * before.norm() * after.norm())) return false;
      for (int w : t)
        if (w != v && (work.V[w] - m).norm() > max_edge) return false;
    }
  work.V[a] = m;
  Eigen::Vector3d n = work.N[a] + work.N[b];
  if (n.norm() > 0) work.N[a] = n.normalized();
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

int collapse_pass(Work& work, double min_edge, double max_edge) {
  std::vector<std::pair<double, Edge>> short_edges;
  for (const auto& t : work.F) {
    if (t[0] < 0) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = t[i], b = t[(i + 1) % 3];
      if (a < b && work.in_box[a] && work.in_box[b] && work.length(a, b) < min_edge) short_edges.push_back({work.length(a, b), {a, b}});
    }
  }
  if (short_edges.empty()) return 0;
  std::sort(short_edges.begin(), short_edges.end());
  std::vector<std::vector<int>> vertex_faces(work.V.size());  // of the vertices in the box only
  for (int f = 0; f < static_cast<int>(work.F.size()); ++f)
    if (work.F[f][0] >= 0)
      for (int v : work.F[f])
        if (work.in_box[v]) vertex_faces[v].push_back(f);
  std::vector<char> locked(work.V.size(), 0);
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

RemeshResult remesh_in_box(const Eigen::AlignedBox3d& box, const RemeshOptions& options, geometry::Mesh& mesh,
                           Eigen::MatrixX3d& N) {
  RemeshResult result;
  if (!(options.max_edge > 0)) return result;
  Work work;
  work.normals = N.rows() == mesh.V.rows();
  for (int i = 0; i < mesh.vertex_count(); ++i) {
    const Eigen::Vector3d p = mesh.V.row(i);
    work.add_vertex(p, work.normals ? Eigen::Vector3d(N.row(i)) : Eigen::Vector3d::Zero(), box.contains(p));
  }
  for (int f = 0; f < mesh.face_count(); ++f) work.F.push_back({mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)});
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    const int splits = split_pass(work, box, options.max_edge);
    result.splits += splits;
    if (splits == 0) break;
  }
  for (int pass = 0; pass < kMaxPasses && options.min_edge > 0; ++pass) {
    const int collapses = collapse_pass(work, options.min_edge, options.max_edge);
    result.collapses += collapses;
    if (collapses == 0) break;
  }
  if (result.splits == 0 && result.collapses == 0) return result;
  std::vector<int> index(work.V.size(), -1);  // vertices keep their order, unused ones dropped
  int vertices = 0, faces = 0;
  for (const auto& t : work.F)
    if (t[0] >= 0) {
      ++faces;
      for (int v : t) index[v] = 0;
    }
  for (int& i : index)
    if (i == 0) i = vertices++;
  mesh.V.resize(vertices, 3);
  if (work.normals) N.resize(vertices, 3);
  for (int v = 0; v < static_cast<int>(work.V.size()); ++v)
    if (index[v] >= 0) {
      mesh.V.row(index[v]) = work.V[v].transpose();
      if (work.normals) N.row(index[v]) = work.N[v].transpose();
    }
  mesh.F.resize(faces, 3);
  faces = 0;
  for (const auto& t : work.F)
    if (t[0] >= 0) mesh.F.row(faces++) << index[t[0]], index[t[1]], index[t[2]];
  return result;
}

}  // namespace reconfig::sculpt
