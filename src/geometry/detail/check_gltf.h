#pragma once
/// @file
/// Checks a glTF or GLB file before Assimp reads it (internal). Assimp 5.2 trusts the lengths
/// a file declares (a 22-byte GLB made it allocate 4 GB), recurses once per level of the node
/// tree (a 20,000-deep chain overflows the stack) and reads buffer URIs wherever they point.

#include <filesystem>
#include <string>

namespace reconfig::geometry::detail {

/// The deepest node tree accepted in a glTF (docs/file-formats.md, "Limits").
inline constexpr int kMaxGltfNodeDepth = 256;

/// Whether Assimp would read `bytes` (a file named `*.<extension>`) as glTF: by extension,
/// the GLB magic or a JSON object.
bool looks_like_gltf(const std::string& extension, const std::string& bytes);

/// Refuses a glTF (JSON text, glTF 1 or 2) or GLB whose declared lengths exceed the data there
/// is (the GLB header and chunks, buffers, buffer views, accessors), whose node tree is deeper
/// than `kMaxGltfNodeDepth` or has a cycle, whose JSON breaks the loaders' limits
/// (strict_json.h), or whose buffer or image URIs lead outside `folder` (unless
/// `allow_outside_paths`). External buffers must be regular files of the declared length.
/// @throws InputError (empty file name) with the JSON path of the problem
void check_gltf(const std::string& bytes, const std::filesystem::path& folder, bool allow_outside_paths);

}  // namespace reconfig::geometry::detail
