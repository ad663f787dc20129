#pragma once
/// @file
/// Undoable edits of a design's list of parts: add, rename, recolor, duplicate, delete.
/// (Replacing a part's geometry is `replace_part_mesh`, edits.h.)
///
/// Each command refuses bad input in `apply` with an InputError naming the part (an empty or
/// taken name, an unknown part, a mesh without triangles) and leaves the design untouched.
/// A command that changes the list itself reports `structure_changed` (part indices shift, the
/// collision service detects every transition again); renaming and recoloring dirty nothing.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "reconfig/geometry/mesh.h"
#include "reconfig/scene/command.h"
#include "reconfig/scene/part.h"

namespace reconfig::scene {

/// Appends a part with geometry `mesh` (its rest pose), made from `source` (a mesh file, a
/// primitive, or `EditedMesh` for geometry that has no file of its own, such as one mesh of a
/// several-mesh glTF). Its pivot is the solid's center of mass; it rests at the identity pose
/// in every state and holds still in every transition.
std::unique_ptr<Command> add_part(std::string name, geometry::Mesh mesh, PartSource source,
                                  std::optional<Eigen::Vector3d> color = std::nullopt);

/// Appends a primitive part (`BoxPrimitive`, `CylinderPrimitive` or `SpherePrimitive` with
/// positive, finite sizes).
std::unique_ptr<Command> add_primitive_part(std::string name, PartSource primitive,
                                            std::optional<Eigen::Vector3d> color = std::nullopt);

/// Renames a part everywhere it is named: its state poses, tracks and linkage attachments.
std::unique_ptr<Command> rename_part(std::string part, std::string new_name);

/// Sets a part's RGB color (components in [0, 1]); nullopt draws it in the default color.
std::unique_ptr<Command> recolor_part(std::string part, std::optional<Eigen::Vector3d> color);

/// Appends a copy of `part` named `new_name`: same geometry, pivot and color, the same pose in
/// every state and the same track in every transition (so it starts inside the original:
/// move it in a state). A linkage-driven part's copy is not driven (it holds still there,
/// which needs its two states to agree: refused otherwise).
std::unique_ptr<Command> duplicate_part(std::string part, std::string new_name);

/// Removes a part. While a transition moves it (it has a track there) the removal is refused
/// with the transitions named, unless `with_tracks`, which removes those tracks too; a part a
/// linkage drives is always refused (edit the drive first). Its state poses go with it.
std::unique_ptr<Command> delete_part(std::string part, bool with_tracks = false);

}  // namespace reconfig::scene
