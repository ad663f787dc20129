#pragma once
/// @file
/// A rigid part of a reconfigurable: its geometry and where that geometry came from.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include "reconfig/geometry/mesh.h"
#include "reconfig/motion/pose.h"

namespace reconfig::scene {

/// Geometry read from a mesh file. `path` is absolute; the scene file stores it relative to
/// itself.
struct MeshFile {
  std::filesystem::path path;
};
/// An axis-aligned box centered at the origin (primitive for quick sketches).
struct BoxPrimitive {
  Eigen::Vector3d size;
};
/// A cylinder along z centered at the origin.
struct CylinderPrimitive {
  double radius = 0, height = 0;
};
/// A sphere centered at the origin.
struct SpherePrimitive {
  double radius = 0;
};
/// Geometry edited in the tool (carved, sculpted, replaced) that has no file yet; saving the
/// scene writes it next to the scene file.
struct EditedMesh {};

using PartSource = std::variant<MeshFile, BoxPrimitive, CylinderPrimitive, SpherePrimitive, EditedMesh>;

/// A rigid part: a closed triangle mesh in its rest pose.
struct Part {
  std::string name;
  PartSource source;
  std::optional<Eigen::Vector3d> color;  ///< RGB in [0, 1]
  geometry::Mesh mesh;                   ///< rest-pose geometry
  /// The pivot c of eq. 9: the solid's center of mass when loaded, unless the file gives
  /// `center`. Replacing the geometry keeps it, so existing poses keep placing the part
  /// where they did.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();

  /// Builds the geometry of a primitive source (boxes, cylinders, spheres).
  static geometry::Mesh primitive_mesh(const PartSource& source);
};

/// The part's rest mesh moved to `pose` (about its pivot): #V×3 positions.
Eigen::MatrixX3d posed_part_vertices(const Part& part, const motion::Pose& pose);

/// The center of mass of the solid bounded by `mesh` (eq. 9's c).
Eigen::Vector3d part_center(const geometry::Mesh& mesh);

}  // namespace reconfig::scene
