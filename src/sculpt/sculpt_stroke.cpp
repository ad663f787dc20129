#include "reconfig/sculpt/sculpt_stroke.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cassert>
#include <limits>
#include <memory>

#include "sculpt/detail/half_step.h"
#include "reconfig/geometry/self_intersections.h"

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

/// What a stroke changed so far, to put back if a later sub-step refuses it.
struct UndoLog {
  std::vector<char> touched;  ///< per point
  std::vector<int> rows;
  std::vector<Eigen::RowVector3d> positions, normals;

  void record(int i, const Eigen::MatrixX3d& V, const Eigen::MatrixX3d& N) {
    if (touched[i]) return;
    touched[i] = 1;
    rows.push_back(i);
    positions.push_back(V.row(i));
    if (N.rows() == V.rows()) normals.push_back(N.row(i));
  }
  void restore(Eigen::MatrixX3d& V, Eigen::MatrixX3d& N) const {
    for (std::size_t k = 0; k < rows.size(); ++k) {
      V.row(rows[k]) = positions[k];
      if (N.rows() == V.rows()) N.row(rows[k]) = normals[k];
    }
  }
  int moved(const Eigen::MatrixX3d& V) const {
    int count = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) count += V.row(rows[k]) != positions[k];
    return count;
  }
};

/// Applies sub-step k to the points in reach; the message of the first failure, or empty.
std::string substep_points(const detail::HalfStep& forward, const detail::HalfStep& backward,
                           const Eigen::AlignedBox3d& reach, Eigen::MatrixX3d& V, Eigen::MatrixX3d& N, double& least,
                           UndoLog& undo) {
  std::vector<int> in_reach;
  for (int i = 0; i < V.rows(); ++i)
    if (reach.contains(V.row(i).transpose())) in_reach.push_back(i);
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
    undo.record(in_reach[k], V, N);
    V.row(in_reach[k]) = out[k].position.transpose();
    if (normals) N.row(in_reach[k]) = out[k].normal.transpose();
  }
  return {};
}

}  // namespace

StrokeResult deform_points(const std::vector<MovingTool>& tools, const StrokeOptions& options, Eigen::MatrixX3d& V,
                           Eigen::MatrixX3d& N) {
  assert(!tools.empty());
  assert(N.rows() == 0 || N.rows() == V.rows());
  StrokeResult result;
  result.substeps = count_substeps(tools, options, result.foldover_bound);
  UndoLog undo;
  undo.touched.assign(V.rows(), 0);
  const double h = 1.0 / result.substeps;
  Placement start = place(tools, options.mirror, 0.0);
  for (int k = 0; k < result.substeps; ++k) {
    const Placement end = place(tools, options.mirror, (k + 1) * h);
    const std::unique_ptr<detail::HalfStep> forward = half_step(tools, start, options, h / 2);
    const std::unique_ptr<detail::HalfStep> backward = half_step(tools, end, options, -h / 2);
    Eigen::AlignedBox3d reach = start.reach;
    reach.extend(end.reach);
    std::string failure = check_grid(*forward, *backward, reach, options.grid, result.min_jacobian_determinant);
    if (failure.empty()) failure = substep_points(*forward, *backward, reach, V, N, result.min_jacobian_determinant, undo);
    if (!failure.empty()) {
      undo.restore(V, N);
      result.refusal = fmt::format("the stroke folds space over at sub-step {} of {}: {}", k + 1, result.substeps, failure);
      return result;
    }
    start = end;
  }
  result.vertices_moved = undo.moved(V);
  result.tools = std::move(start.tools);
  result.applied = true;
  return result;
}

namespace {

/// The stroke one sub-step at a time, the mesh remeshed in each sub-step's reach after it.
StrokeResult deform_and_remesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                               Eigen::MatrixX3d& N) {
  StrokeResult result;
  result.substeps = count_substeps(tools, options, result.foldover_bound);
  StrokeOptions one = options;
  one.substeps = 1;
  std::vector<MovingTool> step = tools;
  for (std::size_t j = 0; j < tools.size(); ++j) step[j].motion = tools[j].motion.fraction(1.0 / result.substeps);
  for (int k = 0; k < result.substeps; ++k) {
    const StrokeResult sub = deform_points(step, one, mesh.V, N);
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
    const RemeshResult remeshed = remesh_in_box(reach, options.remesh, mesh, N);
    result.splits += remeshed.splits;
    result.collapses += remeshed.collapses;
  }
  for (const MovingTool& m : step) result.tools.push_back(m.tool);
  result.applied = true;
  return result;
}

}  // namespace

StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                         Eigen::MatrixX3d& N) {
  geometry::Mesh deformed = mesh;
  Eigen::MatrixX3d normals = N;
  StrokeResult result = options.remesh.max_edge > 0 ? deform_and_remesh(tools, options, deformed, normals)
                                                    : deform_points(tools, options, deformed.V, normals);
  const bool changed = result.vertices_moved > 0 || result.splits > 0 || result.collapses > 0;
  if (result.applied && options.check_self_intersections && changed) {
    const geometry::SelfIntersections after = geometry::find_self_intersections(deformed, 1);
    if (!after.pairs.empty() && !geometry::find_self_intersections(mesh, 0).truncated) {
      result.applied = false;
      result.refusal = fmt::format("the stroke makes the mesh self-intersect (faces {} and {})", after.pairs[0].first,
                                   after.pairs[0].second);
    }
  }
  if (result.applied) {
    mesh = std::move(deformed);
    N = std::move(normals);
  }
  return result;
}

}  // namespace reconfig::sculpt
