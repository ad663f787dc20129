#pragma once
/// @file
/// Volume, center of mass and bounds of the solid a triangle mesh encloses.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// What `mass_properties` measures (unit density).
struct MassProperties {
  /// Signed volume enclosed by the surface (divergence theorem): positive for an outward-oriented
  /// closed mesh, negative for an inward one. Meaningless (origin dependent) for an open mesh.
  double volume = 0;
  /// Total area of the triangles.
  double surface_area = 0;
  /// Center of mass of the enclosed solid. When |volume| is negligible (below 1e-12 × the cube
  /// of the bounding-box diagonal: a flat or open sheet, an empty mesh) there is no solid to
  /// weigh, and this falls back to the area-weighted centroid of the surface (the center of the
  /// bounds if all triangles have zero area, zero for a mesh without faces);
  /// `center_is_surface_centroid` then says so.
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  bool center_is_surface_centroid = false;
  /// Box of the vertices used by faces (empty for a mesh without faces).
  Eigen::AlignedBox3d bounds;
};

/// Volume, area, center of mass and bounds of `mesh`.
///
/// Sums signed tetrahedra joining each triangle to a reference point. The reference is the
/// center of the bounding box rather than the origin: the same result for a closed mesh, with
/// much less cancellation for a part far from the origin.
/// @param mesh  #V×3 positions, #F×3 triangles (outward for a positive volume)
/// @throws InputError (location `face <i>`) if a face refers to a vertex that does not exist
MassProperties mass_properties(const Mesh& mesh);

}  // namespace reconfig::geometry
