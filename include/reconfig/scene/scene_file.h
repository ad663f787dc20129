#pragma once
/// @file
/// Reading and writing the "reconfig-scene" JSON format (docs/file-formats.md).

#include <filesystem>
#include <string>

#include "reconfig/scene/reconfigurable.h"

namespace reconfig::scene {

struct SceneLoadOptions {
  /// Let mesh paths (and a glTF mesh's URIs) lead outside the scene's folder: absolute paths,
  /// `..` out of it, symbolic links out of it (`--allow-outside-paths`). Linkage files may lie
  /// anywhere: they give joint positions, never mesh data a design could export.
  bool allow_outside_paths = false;
};

/// Loads a scene file and the meshes it references (relative to the file), builds primitive
/// parts, computes centers of mass and validates the whole design (validate_scene.h).
/// Only a regular file of at most `kMaxInputFileBytes` is read, and the meshes it refers to
/// must lie in its folder or below unless `options` allow otherwise (docs/file-formats.md,
/// "Limits").
/// @throws InputError naming the file and the JSON path of the first problem
Reconfigurable load_scene(const std::filesystem::path& file, const SceneLoadOptions& options = {});

/// Parses scene JSON text. Mesh paths are resolved against `base_dir` (and must stay inside
/// it, unless `options` allow otherwise); errors name `file_label`.
/// @throws InputError
Reconfigurable parse_scene(const std::string& json_text, const std::filesystem::path& base_dir,
                           const std::string& file_label, const SceneLoadOptions& options = {});

/// The scene as JSON text (2-space indented). Mesh paths are written relative to `base_dir`.
std::string scene_to_json(const Reconfigurable& scene, const std::filesystem::path& base_dir);

/// Writes the mesh of every part whose geometry was edited in the tool (`EditedMesh`) as an OBJ
/// file `<mesh_dir>/<part name>.obj` (characters other than letters, digits, '-' and '_' become
/// '_'), and makes those parts `MeshFile` parts of `scene`.
/// @throws InputError if a file cannot be written
void write_edited_meshes(Reconfigurable& scene, const std::filesystem::path& mesh_dir);

/// Writes the scene atomically (temporary file, then rename): a crash never leaves a half
/// file. Parts whose geometry was edited in the tool (`EditedMesh`) are written as OBJ files
/// under `meshes/` next to the scene and become `MeshFile` parts (`write_edited_meshes`).
/// @throws InputError if the file cannot be written
void save_scene(Reconfigurable& scene, const std::filesystem::path& file);

}  // namespace reconfig::scene
