#pragma once
/// @file
/// Local remeshing between a stroke's sub-steps (Sweepers §5.1): edges split where they grew
/// too long and collapsed where they shrank too short, inside a box only, so a pulled feature
/// keeps its resolution and the mesh stays a closed, oriented manifold.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "reconfig/geometry/mesh.h"

namespace reconfig::sculpt {

struct RemeshOptions {
  double max_edge = 0;  ///< split edges longer than this (> 0; 0 turns remeshing off)
  double min_edge = 0;  ///< collapse edges shorter than this (< max_edge / 2; 0: never collapse)
};

struct RemeshResult {
  int splits = 0;
  int collapses = 0;
};

/// Splits edges longer than `max_edge` with an endpoint in `box` at their midpoints (longest
/// first, both adjacent triangles split in two), then collapses edges shorter than `min_edge`
/// with both endpoints in `box` to their midpoints when that keeps the mesh manifold (the link
/// condition: the endpoints share exactly the two opposite vertices), turns no triangle over
/// and makes no edge longer than `max_edge`. Faces with no vertex in the box are not changed;
/// vertices and faces are renumbered when collapses remove some (faces keep their order).
/// New vertices get the normalized mean of their edge's normals.
///
/// @param box      where the mesh may change
/// @param options  edge-length targets
/// @param mesh     #V×3, #F×3 closed, oriented, manifold; changed in place
/// @param N        #V×3 unit vertex normals, kept in step with the vertices, or empty
RemeshResult remesh_in_box(const Eigen::AlignedBox3d& box, const RemeshOptions& options, geometry::Mesh& mesh,
                           Eigen::MatrixX3d& N);

}  // namespace reconfig::sculpt
