#pragma once
/// @file
/// `remesh_in_box` as a stroke uses it: the vertices in the box found by the mesh's index, and
/// every change reported (for the stroke's undo log and to keep the index up to date), the
/// faces collapses removed left for `compact` to drop.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

#include "reconfig/geometry/mesh.h"
#include "reconfig/sculpt/mesh_index.h"
#include "reconfig/sculpt/remesh_in_box.h"
#include "reconfig/sculpt/sculpt_mesh.h"

namespace reconfig::sculpt::detail {

/// What a remesh changed.
struct RemeshChanges {
  int old_vertices = 0, old_faces = 0;      ///< the mesh's counts before; new ones are appended
  std::vector<int> faces = {};                   ///< the faces changed or appended (mesh numbers)
  std::vector<std::array<int, 3>> before = {};   ///< their corners before ({−1, −1, −1}: appended)
  std::vector<int> moved = {};                   ///< vertices (< old_vertices) collapses moved
  std::vector<Eigen::Vector3d> moved_from = {};  ///< their positions before
  std::vector<Eigen::Vector3d> moved_normal_from = {};  ///< their normals before (if N is kept)
  std::vector<int> removed_faces = {};           ///< faces collapses removed (still in the mesh)
};

/// `remesh_in_box`, without the final compaction.
/// @param mesh   changed in place; its own index is neither queried nor updated
/// @param index  the one to query (the mesh's, or null: a scan)
RemeshResult remesh(const Eigen::AlignedBox3d& box, const RemeshOptions& options, const MeshIndex* index,
                    SculptMesh& mesh, RemeshChanges& changes);

/// Drops `removed_faces` and the vertices no face uses any more; the rest keep their order.
void compact(const std::vector<int>& removed_faces, SculptMesh& mesh);

}  // namespace reconfig::sculpt::detail
