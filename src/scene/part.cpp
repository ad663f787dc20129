#include "reconfig/scene/part.h"

#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/primitives.h"

namespace reconfig::scene {

geometry::Mesh Part::primitive_mesh(const PartSource& source) {
  if (const auto* box = std::get_if<BoxPrimitive>(&source)) return geometry::make_box(box->size);
  if (const auto* cylinder = std::get_if<CylinderPrimitive>(&source))
    return geometry::make_cylinder(cylinder->radius, cylinder->height);
  if (const auto* sphere = std::get_if<SpherePrimitive>(&source)) return geometry::make_sphere(sphere->radius);
  return {};
}

Eigen::Vector3d part_center(const geometry::Mesh& mesh) { return geometry::mass_properties(mesh).center_of_mass; }

Eigen::MatrixX3d posed_part_vertices(const Part& part, const motion::Pose& pose) {
  const Eigen::Isometry3d M = pose.to_isometry(part.center);
  return (part.mesh.V * M.linear().transpose()).rowwise() + M.translation().transpose();
}

}  // namespace reconfig::scene
