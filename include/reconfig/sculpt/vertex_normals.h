#pragma once
/// @file
/// Unit vertex normals of a triangle mesh, to deform along with its vertices.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "reconfig/geometry/mesh.h"

namespace reconfig::sculpt {

/// Angle-weighted vertex normals (Thürmer & Wüthrich), unit length (zero for a vertex no
/// non-degenerate face uses).
/// @param mesh  #V×3, #F×3 outward-oriented
/// @return #V×3 normals
Eigen::MatrixX3d vertex_normals(const geometry::Mesh& mesh);

}  // namespace reconfig::sculpt
