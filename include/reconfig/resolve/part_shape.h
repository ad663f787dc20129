#pragma once
/// @file
/// A part's rest geometry prepared for the contour and penetration queries of `resolve`.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <vector>

#include "reconfig/geometry/certain_plane.h"
#include "reconfig/geometry/mesh.h"
#include "reconfig/geometry/signed_distance.h"

namespace reconfig::resolve {

/// Built once per geometry (the part is rigid), queried at any pose: the triangle tree and the
/// signed distance of the rest mesh, and surface samples for the penetration term.
struct PartShape {
  /// @param mesh         the part's closed rest mesh (#V×3, #F×3, at least one triangle)
  /// @param max_samples  at most this many surface samples (vertices, evenly strided)
  explicit PartShape(const geometry::Mesh& mesh, int max_samples = 256);

  geometry::MeshSignedDistance distance;  ///< also holds the triangle tree of the rest mesh
  Eigen::AlignedBox3d bounds;             ///< box of the rest mesh
  /// Rest positions of the surface samples and their area weights (summing to 1): each sample
  /// stands for its share of the surface (a third of the area of the faces around it).
  std::vector<Eigen::Vector3d> sample_points;
  std::vector<double> sample_weights;
  /// neighbors[f][k]: the face across edge k (corners k → k+1) of face f; −1 on a boundary or
  /// a non-manifold edge.
  std::vector<std::array<int, 3>> neighbors;
  /// planes[k]: the plane of face tree().leaf_order()[k] in the rest frame, for the contour's
  /// side filter (in leaf order: a pair query reads the planes of a leaf together).
  std::vector<geometry::CertainPlane> planes;
  /// Every edge has exactly two faces (no −1 in `neighbors`).
  bool closed = false;
  /// Closed, and the two faces of every edge run it in opposite directions: a ray's winding
  /// count (`geometry/ray_winding.h`) is the winding number, 0 exactly outside the solid.
  bool oriented = false;

  const geometry::TriangleBvh& tree() const { return distance.tree(); }
};

}  // namespace reconfig::resolve
