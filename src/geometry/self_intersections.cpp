#include "reconfig/geometry/self_intersections.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/detail/exact_predicates.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/triangle_bvh.h"

namespace reconfig::geometry {
namespace {

using detail::Vec3;

constexpr int kParallelFaces = 2048;  ///< below this many faces the search runs serially

Vec3 position(const Mesh& mesh, int v) { return mesh.V.row(v).transpose(); }

/// The part of a face "opposite" its shared corner v: the other corners `others` (distinct
/// vertex indices ≠ v's) as pieces that do not contain v. Two corners p, q give the segment
/// pq unless v lies on it (a zero-area face with v inside); then the points p, q themselves.
/// A piece is (points, count). Corners at v's position are dropped.
struct FarPieces {
  Vec3 points[2][2];
  int size[2] = {0, 0};
  int count = 0;
  void add(const Vec3* p, int n) {
    for (int i = 0; i < n; ++i) points[count][i] = p[i];
    size[count++] = n;
  }
};

FarPieces far_pieces(const Vec3& v, const Vec3* others, int n) {
  FarPieces pieces;
  if (n == 2) {
    if (!detail::hulls_intersect(&v, 1, others, 2)) {
      pieces.add(others, 2);
      return pieces;
    }
  }
  for (int i = 0; i < n; ++i)
    if (others[i] != v) pieces.add(&others[i], 1);
  return pieces;
}

/// Faces sharing exactly the corner v (position pv): improper iff they share a point ≠ v.
/// The shared set is convex and contains v, so it holds another point iff one of its vertices
/// differs from v; such a vertex lies on a far piece of one face and in the other face.
bool improper_at_vertex(const Vec3& pv, const Vec3* a, const Vec3* a_others, int na, const Vec3* b,
                        const Vec3* b_others, int nb) {
  const FarPieces fa = far_pieces(pv, a_others, na);
  for (int i = 0; i < fa.count; ++i)
    if (detail::hulls_intersect(fa.points[i], fa.size[i], b, 3)) return true;
  const FarPieces fb = far_pieces(pv, b_others, nb);
  for (int i = 0; i < fb.count; ++i)
    if (detail::hulls_intersect(fb.points[i], fb.size[i], a, 3)) return true;
  return false;
}

void validate(const Mesh& mesh) {
  const int nv = mesh.vertex_count();
  for (int f = 0; f < mesh.face_count(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.F(f, c);
      if (v < 0 || v >= nv)
        throw InputError("", "face " + std::to_string(f),
                         "vertex index " + std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
      if (!mesh.V.row(v).allFinite())
        throw InputError("", "face " + std::to_string(f),
                         "vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
}

}  // namespace

bool faces_intersect_improperly(const Mesh& mesh, int f, int g) {
  if (f == g) return false;
  const int ia[3] = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
  const int ib[3] = {mesh.F(g, 0), mesh.F(g, 1), mesh.F(g, 2)};
  const Vec3 a[3] = {position(mesh, ia[0]), position(mesh, ia[1]), position(mesh, ia[2])};
  const Vec3 b[3] = {position(mesh, ib[0]), position(mesh, ib[1]), position(mesh, ib[2])};

  // Distinct vertex indices of each face, and those of a that b shares.
  const auto distinct = [](const int* idx, int* out) {
    int n = 0;
    for (int c = 0; c < 3; ++c)
      if (std::find(out, out + n, idx[c]) == out + n) out[n++] = idx[c];
    return n;
  };
  int da[3], db[3], shared[3];
  const int na = distinct(ia, da), nb = distinct(ib, db);
  int ns = 0;
  for (int i = 0; i < na; ++i)
    if (std::find(db, db + nb, da[i]) != db + nb) shared[ns++] = da[i];

  // Distinct corners of a face other than the shared ones.
  const auto others = [&](const int* d, int n, Vec3* out) {
    int k = 0;
    for (int i = 0; i < n; ++i)
      if (std::find(shared, shared + ns, d[i]) == shared + ns) out[k++] = position(mesh, d[i]);
    return k;
  };
  Vec3 oa[3], ob[3];
  const int noa = others(da, na, oa), nob = others(db, nb, ob);

  switch (ns) {
    case 0:
      return detail::hulls_intersect(a, 3, b, 3);
    case 1:
      return improper_at_vertex(position(mesh, shared[0]), a, oa, noa, b, ob, nob);
    case 2: {
      const Vec3 pu = position(mesh, shared[0]), pv = position(mesh, shared[1]);
      if (noa == 0 || nob == 0) return false;  // a face that is just the edge uv lies in the other
      if (pu == pv) return improper_at_vertex(pu, a, oa, noa, b, ob, nob);
      const Vec3& pa = oa[0];
      const Vec3& pb = ob[0];
      const bool flat_a = detail::collinear(pu, pv, pa), flat_b = detail::collinear(pu, pv, pb);
      if (!flat_a && !flat_b)  // folded onto each other: coplanar, third corners on one side
        return detail::coplanar(pu, pv, pa, pb) && detail::coplanar_orientation(pu, pv, pa, pb) > 0;
      if (flat_a && flat_b)  // two segments on line uv, both reaching past the same end
        return (detail::strictly_ordered_along_line(pu, pv, pa) && detail::strictly_ordered_along_line(pu, pv, pb)) ||
               (detail::strictly_ordered_along_line(pv, pu, pa) && detail::strictly_ordered_along_line(pv, pu, pb));
      return false;  // a proper face meets line uv only in the segment uv
    }
    default:  // same three vertices: a duplicate face overlaps entirely unless it has no area
      return !detail::collinear(a[0], a[1], a[2]);
  }
}

SelfIntersections find_self_intersections(const Mesh& mesh, int max_pairs, const ProgressCallback& progress) {
  max_pairs = std::max(max_pairs, 0);
  validate(mesh);
  SelfIntersections result;
  const int n = mesh.face_count();
  if (n < 2) return result;
  const TriangleBvh bvh(mesh.V, mesh.F);

  const auto search_face = [&](int f, std::vector<std::pair<int, int>>& out) {
    Eigen::AlignedBox3d box(position(mesh, mesh.F(f, 0)));
    box.extend(position(mesh, mesh.F(f, 1)));
    box.extend(position(mesh, mesh.F(f, 2)));
    bvh.for_each_overlapping(box, [&](int g) {
      if (g > f && faces_intersect_improperly(mesh, f, g)) out.emplace_back(f, g);
    });
  };

  // Faces in ascending chunks: after each chunk every pair (f, g) with f in a processed chunk
  // is known, so once more than max_pairs are found the smallest max_pairs are final.
  const int chunk = std::max(1024, n / 64);
  std::vector<std::pair<int, int>>& pairs = result.pairs;
  for (int begin = 0; begin < n; begin += chunk) {
    const int end = std::min(n, begin + chunk);
    if (n < kParallelFaces) {
      for (int f = begin; f < end; ++f) search_face(f, pairs);
    } else {
      tbb::enumerable_thread_specific<std::vector<std::pair<int, int>>> found;
      tbb::parallel_for(tbb::blocked_range<int>(begin, end, 64), [&](const tbb::blocked_range<int>& range) {
        auto& local = found.local();
        for (int f = range.begin(); f < range.end(); ++f) search_face(f, local);
      });
      for (const auto& local : found) pairs.insert(pairs.end(), local.begin(), local.end());
    }
    if (static_cast<int>(pairs.size()) > max_pairs) break;
    if (!report_progress(progress, static_cast<double>(end) / n)) {
      result.cancelled = end < n;
      break;
    }
  }
  std::sort(pairs.begin(), pairs.end());
  if (static_cast<int>(pairs.size()) > max_pairs) {
    pairs.resize(max_pairs);
    result.truncated = true;
  }
  return result;
}

}  // namespace reconfig::geometry
