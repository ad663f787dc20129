#include "reconfig/sculpt/sculpt_stroke.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cassert>
#include <limits>
#include <memory>

#include "sculpt/detail/half_step.h"
#include "sculpt/detail/remesh.h"
#include "reconfig/geometry/self_intersections.h"
#include "reconfig/sculpt/sculpt_mesh.h"

namespace reconfig::sculpt {
namespace {

/// Below this many points in reach a sub-step runs on one thread.
constexpr int kParallelThreshold = 2048;

/// The map of one sub-step at a point: the forward half-step, then the inverse of the backward one.
struct SubstepPoint {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
  double determinant = 1;
  bool solved = true;
};

SubstepPoint substep_at(const detail::HalfStep& forward, const detail::HalfStep& backward, const Eigen::Vector3d& p,
                        const Eigen::Vector3d* normal) {
  SubstepPoint out;
  Eigen::Vector3d middle;
  Eigen::Matrix3d J1, J2;
  const bool moved_forward = forward.apply(p, middle, J1);
  out.solved = backward.solve(middle, out.position, J2);
  if (!out.solved) return out;
  if (normal) out.normal = *normal;
  if (!moved_forward && out.position == middle) return out;  // bit for bit: this point is out of reach
  const double det1 = J1.determinant(), det2 = J2.determinant();
  out.determinant = det2 > 0 ? det1 / det2 : det2;  // a backward half-step that folds is the measure
  if (normal && det1 > 0 && det2 > 0) {  // cof(J) n ∝ J⁻ᵀ n with J = J2⁻¹ J1
    out.normal = (J2.transpose() * J1.inverse().transpose() * *normal).normalized();
  }
  return out;
}

/// The tools' placements at one instant of the stroke, and their field boxes.
struct Placement {
  std::vector<Tool> tools;
  Eigen::AlignedBox3d reach;  ///< every point any tool (or its mirror image) touches
};

Placement place(const std::vector<MovingTool>& moving, const MirrorPlane& mirror, double alpha) {
  Placement placement;
  for (const MovingTool& m : moving) {
    Tool tool = m.tool;
    tool.set_pose(m.motion.apply(m.tool.pose(), alpha));
    const Eigen::AlignedBox3d box = tool.field_box();
    placement.reach.extend(box);
    if (mirror.axis >= 0) {
      placement.reach.extend(detail::reflect(mirror, box.min()));
      placement.reach.extend(detail::reflect(mirror, box.max()));
    }
    placement.tools.push_back(std::move(tool));
  }
  return placement;
}

std::unique_ptr<detail::HalfStep> half_step(const std::vector<MovingTool>& moving, const Placement& placement,
                                            const StrokeOptions& options, double c) {
  if (moving.size() == 1 && options.mirror.axis < 0 && !options.blended)
    return std::make_unique<detail::ClosedFormHalfStep>(placement.tools[0], moving[0].motion, c);
  std::vector<ToolMotion> motions;
  for (const MovingTool& m : moving) motions.push_back(m.motion);
  return std::make_unique<detail::BlendedHalfStep>(placement.tools, motions, options.mirror, c);
}

int count_substeps(const std::vector<MovingTool>& tools, const StrokeOptions& options, double& bound) {
  std::vector<MovingTool> all = tools;
  if (options.mirror.axis >= 0) all.insert(all.end(), tools.begin(), tools.end());  // same terms in eq. (3)
  bound = foldover_bound(all);
  return options.substeps > 0 ? options.substeps : substep_count(all);
}

std::string point_text(const Eigen::Vector3d& p) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x(), p.y(), p.z()); }

/// Measures det J of the sub-step on a grid over `box`; the message of the first failure, or empty.
std::string check_grid(const detail::HalfStep& forward, const detail::HalfStep& backward, const Eigen::AlignedBox3d& box,
                       int grid, double& least) {
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j)
      for (int k = 0; k < grid; ++k) {
        const Eigen::Vector3d t = (Eigen::Vector3d(i, j, k) + Eigen::Vector3d::Constant(0.5)) / grid;
        const Eigen::Vector3d p = box.min() + t.cwiseProduct(box.sizes());
        const SubstepPoint q = substep_at(forward, backward, p, nullptr);
        if (!q.solved) return "the sub-step cannot be inverted at " + point_text(p);
        least = std::min(least, q.determinant);
        if (!(q.determinant > 0)) return fmt::format("Jacobian determinant {:.3g} at {}", q.determinant, point_text(p));
      }
  return {};
}

/// What a stroke changed so far, to put back if a later sub-step or check refuses it: the
/// first position (and normal) of every vertex it moved, the first corners of every face it
/// changed and the counts before (what was appended is dropped). Once remeshing compacts the
/// mesh (collapses renumber it), the mesh as it was, rebuilt from the log, instead.
class StrokeUndo {
 public:
  StrokeUndo(int vertices, int faces, bool normals)
      : vertices_(vertices), faces_(faces), normals_(normals), vertex_seen_(vertices_, 0), face_seen_(faces_, 0) {}

  void record_vertex(int v, const Eigen::Vector3d& position, const Eigen::Vector3d& normal) {
    if (whole_ || v >= vertices_ || vertex_seen_[v]) return;
    vertex_seen_[v] = 1;
    rows_.push_back(v);
    positions_.push_back(position);
    if (normals_) normals_v_.push_back(normal);
  }
  void record_face(int f, const std::array<int, 3>& corners) {
    if (whole_ || f >= faces_ || face_seen_[f]) return;
    face_seen_[f] = 1;
    face_rows_.push_back(f);
    face_corners_.push_back(corners);
  }
  /// Keeps the mesh as it was whole (before a compaction renumbers it); the log stops.
  void keep_whole(const SculptMesh& mesh) {
    if (whole_) return;
    whole_ = std::make_unique<geometry::Mesh>(mesh.mesh());
    whole_N_ = mesh.normals();
    Eigen::Ref<Eigen::MatrixX3i> F = whole_->F;
    put_back_rows(whole_->V, whole_N_, &F);
    whole_->V.conservativeResize(vertices_, 3);
    whole_->F.conservativeResize(faces_, 3);
    if (normals_) whole_N_.conservativeResize(vertices_, 3);
  }
  /// Puts the points back (`deform_points`: no vertex was added).
  void restore(Eigen::Ref<Eigen::MatrixX3d> V, Eigen::Ref<Eigen::MatrixX3d> N) const { put_back_rows(V, N, nullptr); }
  void restore(SculptMesh& mesh) {
    if (!whole_) return put_back(mesh);
    mesh.assign(whole_->V, whole_->F, whole_N_);
  }
  /// The logged vertices that are somewhere else now.
  int moved(const Eigen::Ref<const Eigen::MatrixX3d>& V) const {
    int count = 0;
    for (std::size_t k = 0; k < rows_.size(); ++k) count += V.row(rows_[k]).transpose() != positions_[k];
    return count;
  }

 private:
  void put_back_rows(Eigen::Ref<Eigen::MatrixX3d> V, Eigen::Ref<Eigen::MatrixX3d> N,
                     Eigen::Ref<Eigen::MatrixX3i>* F) const {
    for (std::size_t k = 0; k < rows_.size(); ++k) {
      V.row(rows_[k]) = positions_[k].transpose();
      if (normals_) N.row(rows_[k]) = normals_v_[k].transpose();
    }
    if (!F) return;
    for (std::size_t k = 0; k < face_rows_.size(); ++k)
      F->row(face_rows_[k]) << face_corners_[k][0], face_corners_[k][1], face_corners_[k][2];
  }
  void put_back(SculptMesh& mesh) const {
    Eigen::Ref<Eigen::MatrixX3i> F = mesh.F();
    put_back_rows(mesh.V(), mesh.N(), &F);
    mesh.resize(vertices_, faces_);
  }

  int vertices_, faces_;
  bool normals_;
  std::vector<char> vertex_seen_, face_seen_;  ///< per vertex and face of the mesh before
  std::vector<int> rows_;
  std::vector<Eigen::Vector3d> positions_, normals_v_;
  std::vector<int> face_rows_;
  std::vector<std::array<int, 3>> face_corners_;
  std::unique_ptr<geometry::Mesh> whole_;
  Eigen::MatrixX3d whole_N_;
};

/// The points in `reach`, ascending: from the index, or by a scan of every point.
std::vector<int> points_in(const Eigen::AlignedBox3d& reach, const Eigen::Ref<const Eigen::MatrixX3d>& V,
                           const MeshIndex* index) {
  if (index) return index->vertices_in(reach, V);
  std::vector<int> in_reach;
  for (int i = 0; i < V.rows(); ++i)
    if (reach.contains(V.row(i).transpose())) in_reach.push_back(i);
  return in_reach;
}

/// Applies sub-step k to the points in reach (the index, if any, kept up to date); the message
/// of the first failure, or empty. Counts the points it moved in `moved`.
std::string substep_points(const detail::HalfStep& forward, const detail::HalfStep& backward,
                           const Eigen::AlignedBox3d& reach, Eigen::Ref<Eigen::MatrixX3d> V,
                           Eigen::Ref<Eigen::MatrixX3d> N, double& least, MeshIndex* index, StrokeUndo& undo,
                           int& moved) {
  const std::vector<int> in_reach = points_in(reach, V, index);
  const int n = static_cast<int>(in_reach.size());
  std::vector<SubstepPoint> out(n);
  const bool normals = N.rows() == V.rows();
  auto run = [&](int begin, int end) {
    for (int k = begin; k < end; ++k) {
      const int i = in_reach[k];
      const Eigen::Vector3d normal = normals ? Eigen::Vector3d(N.row(i)) : Eigen::Vector3d::Zero();
      out[k] = substep_at(forward, backward, V.row(i).transpose(), normals ? &normal : nullptr);
    }
  };
  if (n < kParallelThreshold) run(0, n);
  else tbb::parallel_for(tbb::blocked_range<int>(0, n, 512), [&](const tbb::blocked_range<int>& r) { run(r.begin(), r.end()); });
  for (int k = 0; k < n; ++k) {  // in index order: the first failure is deterministic
    const int i = in_reach[k];
    if (!out[k].solved) return fmt::format("the sub-step cannot be inverted at vertex {}", i);
    least = std::min(least, out[k].determinant);
    if (!(out[k].determinant > 0)) return fmt::format("Jacobian determinant {:.3g} at vertex {}", out[k].determinant, i);
  }
  for (int k = 0; k < n; ++k) {
    const int i = in_reach[k];
    const Eigen::Vector3d before = V.row(i).transpose();
    if (out[k].position == before && (!normals || N.row(i).transpose() == out[k].normal)) continue;
    undo.record_vertex(i, before, normals ? Eigen::Vector3d(N.row(i)) : Eigen::Vector3d::Zero());
    moved += out[k].position != before;
    V.row(i) = out[k].position.transpose();
    if (normals) N.row(i) = out[k].normal.transpose();
    if (index) index->move_vertex(i, before, out[k].position);
  }
  return {};
}

/// `deform_points`, the points found by `index` (null: a scan), every change logged in `undo`;
/// a refused stroke is left half done (the caller puts it back). `vertices_moved` sums the
/// points each sub-step moved.
StrokeResult deform(const std::vector<MovingTool>& tools, const StrokeOptions& options, Eigen::Ref<Eigen::MatrixX3d> V,
                    Eigen::Ref<Eigen::MatrixX3d> N, MeshIndex* index, StrokeUndo& undo) {
  assert(!tools.empty());
  assert(N.rows() == 0 || N.rows() == V.rows());
  StrokeResult result;
  result.substeps = count_substeps(tools, options, result.foldover_bound);
  const double h = 1.0 / result.substeps;
  Placement start = place(tools, options.mirror, 0.0);
  for (int k = 0; k < result.substeps; ++k) {
    const Placement end = place(tools, options.mirror, (k + 1) * h);
    const std::unique_ptr<detail::HalfStep> forward = half_step(tools, start, options, h / 2);
    const std::unique_ptr<detail::HalfStep> backward = half_step(tools, end, options, -h / 2);
    Eigen::AlignedBox3d reach = start.reach;
    reach.extend(end.reach);
    std::string failure = check_grid(*forward, *backward, reach, options.grid, result.min_jacobian_determinant);
    if (failure.empty())
      failure = substep_points(*forward, *backward, reach, V, N, result.min_jacobian_determinant, index, undo,
                               result.vertices_moved);
    if (!failure.empty()) {
      result.refusal = fmt::format("the stroke folds space over at sub-step {} of {}: {}", k + 1, result.substeps, failure);
      return result;
    }
    start = end;
  }
  result.tools = std::move(start.tools);
  result.applied = true;
  return result;
}

}  // namespace

StrokeResult deform_points(const std::vector<MovingTool>& tools, const StrokeOptions& options, Eigen::MatrixX3d& V,
                           Eigen::MatrixX3d& N) {
  StrokeUndo undo(static_cast<int>(V.rows()), 0, N.rows() == V.rows());
  StrokeResult result = deform(tools, options, V, N, nullptr, undo);
  if (!result.applied) undo.restore(V, N);
  result.vertices_moved = undo.moved(V);
  return result;
}

namespace {

/// Logs what a remesh changed and keeps the index up to date with it; a compaction (after
/// collapses) keeps the mesh as it was in the log and indexes the compacted mesh anew.
void apply_remesh_changes(const detail::RemeshChanges& changes, SculptMesh& mesh, StrokeUndo& undo) {
  const bool normals = mesh.has_normals();
  for (std::size_t k = 0; k < changes.moved.size(); ++k)
    undo.record_vertex(changes.moved[k], changes.moved_from[k], normals ? changes.moved_normal_from[k] : Eigen::Vector3d());
  for (std::size_t k = 0; k < changes.faces.size(); ++k)
    if (changes.before[k][0] >= 0) undo.record_face(changes.faces[k], changes.before[k]);
  if (!changes.removed_faces.empty()) {
    undo.keep_whole(mesh);
    detail::compact(changes.removed_faces, mesh);
    mesh.reindex();
    return;
  }
  MeshIndex& index = mesh.index();
  const auto V = mesh.V();
  const auto F = mesh.F();
  for (int v = changes.old_vertices; v < mesh.vertex_count(); ++v) index.add_vertex(V.row(v).transpose());
  for (std::size_t k = 0; k < changes.faces.size(); ++k) {
    const int f = changes.faces[k];
    index.change_face(f, changes.before[k], {F(f, 0), F(f, 1), F(f, 2)});
  }
}

/// The stroke one sub-step at a time, the mesh remeshed in each sub-step's reach after it.
StrokeResult deform_and_remesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, SculptMesh& mesh,
                               StrokeUndo& undo) {
  StrokeResult result;
  result.substeps = count_substeps(tools, options, result.foldover_bound);
  StrokeOptions one = options;
  one.substeps = 1;
  std::vector<MovingTool> step = tools;
  for (std::size_t j = 0; j < tools.size(); ++j) step[j].motion = tools[j].motion.fraction(1.0 / result.substeps);
  for (int k = 0; k < result.substeps; ++k) {
    const StrokeResult sub = deform(step, one, mesh.V(), mesh.N(), &mesh.index(), undo);
    result.min_jacobian_determinant = std::min(result.min_jacobian_determinant, sub.min_jacobian_determinant);
    if (!sub.applied) {
      result.refusal = fmt::format("the stroke folds space over at sub-step {} of {}: {}", k + 1, result.substeps,
                                   sub.refusal.substr(sub.refusal.find(": ") + 2));
      return result;
    }
    result.vertices_moved += sub.vertices_moved;
    Eigen::AlignedBox3d reach = place(step, options.mirror, 0.0).reach;
    for (std::size_t j = 0; j < step.size(); ++j) step[j].tool = sub.tools[j];
    reach.extend(place(step, options.mirror, 0.0).reach);
    detail::RemeshChanges changes;
    const RemeshResult remeshed = detail::remesh(reach, options.remesh, &mesh.index(), mesh, changes);
    apply_remesh_changes(changes, mesh, undo);
    result.splits += remeshed.splits;
    result.collapses += remeshed.collapses;
  }
  for (const MovingTool& m : step) result.tools.push_back(m.tool);
  result.applied = true;
  return result;
}

}  // namespace

StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, SculptMesh& mesh) {
  if (mesh.index().vertex_count() != mesh.vertex_count() || mesh.index().face_count() != mesh.face_count())
    mesh.reindex();
  StrokeUndo undo(mesh.vertex_count(), mesh.face_count(), mesh.has_normals());
  StrokeResult result = options.remesh.max_edge > 0 ? deform_and_remesh(tools, options, mesh, undo)
                                                    : deform(tools, options, mesh.V(), mesh.N(), &mesh.index(), undo);
  if (options.remesh.max_edge <= 0) result.vertices_moved = undo.moved(mesh.V());
  const bool changed = result.vertices_moved > 0 || result.splits > 0 || result.collapses > 0;
  bool restored = false;
  if (result.applied && options.check_self_intersections && changed) {
    const geometry::SelfIntersections after = geometry::find_self_intersections(mesh.mesh(), 1);
    if (!after.pairs.empty()) {  // refused unless the mesh self-intersected before the stroke
      SculptMesh deformed = mesh;
      undo.restore(mesh);
      restored = true;
      if (!geometry::find_self_intersections(mesh.mesh(), 0).truncated) {
        result.applied = false;
        result.refusal = fmt::format("the stroke makes the mesh self-intersect (faces {} and {})", after.pairs[0].first,
                                     after.pairs[0].second);
      } else {
        mesh = std::move(deformed);
        restored = false;
      }
    }
  }
  if (!result.applied) {
    if (!restored) undo.restore(mesh);
    mesh.reindex();
  }
  return result;
}

StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                         Eigen::MatrixX3d& N, MeshIndex& index) {
  SculptMesh sculpted = SculptMesh::adopt(std::move(mesh), std::move(N), std::move(index));
  const StrokeResult result = sculpt_mesh(tools, options, sculpted);
  sculpted.release(mesh, N, index);
  return result;
}

StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                         Eigen::MatrixX3d& N) {
  MeshIndex index(mesh);
  return sculpt_mesh(tools, options, mesh, N, index);
}

}  // namespace reconfig::sculpt
