#pragma once
/// @file
/// One stroke: tools moving along their paths deform space, and the points, normals or mesh
/// embedded in it, in foldover-free sub-steps that are measured, never assumed (Sweepers §3–4).

#include <Eigen/Core>

#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/sculpt/mesh_index.h"
#include "reconfig/sculpt/remesh_in_box.h"
#include "reconfig/sculpt/sculpt_mesh.h"
#include "reconfig/sculpt/substep_count.h"

namespace reconfig::sculpt {

/// A mirror plane {x : x[axis] = offset}: each tool gets a mirror image whose field and path
/// are the reflections of its own, blended with it (Sweepers Fig. 1: model one side, the
/// other follows).
struct MirrorPlane {
  int axis = -1;      ///< 0, 1 or 2; −1: no mirror
  double offset = 0;  ///< where the plane cuts the axis
};

struct StrokeOptions {
  /// 0: the least count above the foldover bound (`substep_count`, the mirror images counted
  /// as tools); > 0 forces this many — fewer than the bound may fold space, which the checks
  /// then find and the stroke is refused.
  int substeps = 0;
  /// The Jacobian determinant is measured, at every sub-step, on a grid of `grid`³ points over
  /// the tools' field boxes (and at every vertex in them). 0: at the vertices only.
  int grid = 8;
  /// Use the general log-space blend (eq. 2, Jacobians by finite differences) even for one
  /// tool; otherwise one tool without mirror takes the closed forms of §4.1–4.3.
  bool blended = false;
  MirrorPlane mirror = {};
  /// `sculpt_mesh` only: refuse the stroke if the deformed mesh self-intersects (and the
  /// input did not).
  bool check_self_intersections = true;
  /// `sculpt_mesh` only: remesh inside the sub-step's reach after every sub-step (§5.1).
  RemeshOptions remesh = {};
};

/// What a stroke did, or why it was refused.
struct StrokeResult {
  bool applied = false;        ///< false: refused, the input is left exactly as it was
  std::string refusal;         ///< why it was refused (empty if applied)
  int substeps = 0;            ///< s
  double foldover_bound = 0;   ///< the bound s had to exceed (eq. 3)
  /// The least Jacobian determinant of one sub-step's map, over the grid samples and the
  /// vertices of every sub-step (1 if nothing was in reach). > 0: no sub-step folds space.
  double min_jacobian_determinant = 1;
  int vertices_moved = 0;      ///< vertices that ended somewhere else (without remeshing)
  int splits = 0, collapses = 0;  ///< edges split and collapsed by remeshing
  std::vector<Tool> tools;     ///< the tools where the stroke left them (for the next stroke)
};

/// Deforms points (and their normals) by the tools moving along their paths, in s sub-steps.
/// Each sub-step k is the half-step forward with the tools where they are at k/s, followed by
/// the inverse of a half-step backward with the tools where they are at (k+1)/s; the inverse
/// stroke (`ToolMotion::inverse`, starting where the stroke ended) therefore undoes it (up to
/// the 1e-12 solver tolerance). Points where every tool's field is 0 at both ends of a
/// sub-step are not touched (bit for bit); points inside a tool follow it exactly.
/// Normals are mapped by the Jacobian's co-matrix and renormalized.
///
/// @param tools    the tools and their paths (≥ 1); all sub-steps use the same s
/// @param options  sub-steps, checks, mirror
/// @param V        #V×3 points, deformed in place (left unchanged if the stroke is refused)
/// @param N        #V×3 unit normals, deformed in place, or empty
/// @return the measurements; refused (nothing changed) if a Jacobian determinant ≤ 0 was found
///   or a sub-step could not be inverted at a point
StrokeResult deform_points(const std::vector<MovingTool>& tools, const StrokeOptions& options, Eigen::MatrixX3d& V,
                           Eigen::MatrixX3d& N);

/// `deform_points` on a mesh's vertices, then (if `check_self_intersections`) the exact
/// self-intersection test of the deformed mesh (geometry/self_intersections.h): a stroke that
/// makes the mesh self-intersect is refused and the mesh left as it was (bit for bit: the
/// stroke works in place and logs what it changes, to put it back). With remeshing, each
/// sub-step is deformed on its own (the same sub-steps: tools at k/s and (k+1)/s) and followed
/// by `remesh_in_box` over the sub-step's reach; `vertices_moved` then counts the vertices
/// moved by the sub-steps, summed.
/// @param tools    as `deform_points`
/// @param options  as `deform_points`
/// @param mesh     #V×3, #F×3, deformed in place
/// @param N        #V×3 unit vertex normals, deformed in place, or empty
StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                         Eigen::MatrixX3d& N);

/// `sculpt_mesh` with the mesh's spatial index kept by the caller from stroke to stroke (a
/// drag): each sub-step and remesh touches only the vertices and faces in its reach, and the
/// index follows them (built anew after collapses renumber the mesh, or a refusal).
/// @param index  of `mesh` (rebuilt first if its vertex or face count differs from the mesh's)
StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, geometry::Mesh& mesh,
                         Eigen::MatrixX3d& N, MeshIndex& index);

/// The same on a `SculptMesh` kept from stroke to stroke (a drag): its index as above (rebuilt
/// first if its counts differ from the mesh's), and the rows remeshing appends go to the room
/// it keeps, so a frame copies no whole matrix.
/// The results are those of the overloads above, bit for bit.
StrokeResult sculpt_mesh(const std::vector<MovingTool>& tools, const StrokeOptions& options, SculptMesh& mesh);

}  // namespace reconfig::sculpt
