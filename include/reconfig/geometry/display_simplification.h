#pragma once
/// @file
/// Coarser copies of meshes for drawing while things move (level of detail): vertex clustering
/// on a uniform grid (Rossignac & Borrel). For display only — the result may be non-manifold;
/// collision detection always uses the exact geometry.

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// Merges the vertices in each cell of a grid of cubes of side `cell` (aligned with the mesh's
/// bounding box corner) into their mean, keeps the triangles whose corners land in three
/// different cells, once each. Every output vertex lies within √3·cell of each input vertex
/// of its cell, and every input vertex within √3·cell of an output vertex.
/// @param cell > 0
Mesh cluster_vertices(const Mesh& mesh, double cell);

/// The mesh with at most `max_triangles` triangles: itself if it has no more, else
/// `cluster_vertices` with the smallest cell (found by bisection, to about 5 %) that gets there.
Mesh simplify_for_display(const Mesh& mesh, int max_triangles);

}  // namespace reconfig::geometry
