#pragma once
/// @file
/// The triangle mesh every module passes around.

#include <Eigen/Core>

namespace reconfig::geometry {

/// A triangle mesh: the boundary of a rigid part's solid, counter-clockwise faces seen from
/// outside (outward normals).
struct Mesh {
  Eigen::MatrixX3d V;  ///< #V×3 vertex positions
  Eigen::MatrixX3i F;  ///< #F×3 vertex indices into V, one row per triangle

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int face_count() const { return static_cast<int>(F.rows()); }
  bool empty() const { return F.rows() == 0; }
};

}  // namespace reconfig::geometry
