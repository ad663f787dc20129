#include "reconfig/geometry/load_mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/LU>

#include <cctype>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/detail/check_gltf.h"
#include "geometry/detail/read_obj.h"
#include "geometry/detail/read_off.h"
#include "geometry/detail/read_ply.h"
#include "geometry/detail/weld_vertices.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/read_input_file.h"

namespace reconfig::geometry {
namespace {

constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_ValidateDataStructure;

std::string lower_extension(std::string hint) {
  if (!hint.empty() && hint.front() == '.') hint.erase(0, 1);
  for (char& c : hint) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return hint;
}

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out(r, c) = static_cast<double>(m[r][c]);
  return out;
}

/// Every instance of every mesh of `scene` (or of mesh `only` alone), placed by its node
/// transforms, merged and welded. Throws InputError with an empty file name.
Mesh scene_to_mesh(const aiScene& scene, std::optional<unsigned> only = std::nullopt) {
  std::vector<Eigen::Vector3d> corners;  // raw vertices, one block per placed mesh
  std::vector<Eigen::Vector3i> faces;    // indices into `corners`
  const bool several_meshes = scene.mNumMeshes > 1;

  auto add_mesh = [&](unsigned mesh_index, const Eigen::Matrix4d& transform) {
    if (mesh_index >= scene.mNumMeshes || scene.mMeshes[mesh_index] == nullptr)
      throw InputError("", "mesh " + std::to_string(mesh_index), "node refers to a missing mesh");
    const aiMesh& mesh = *scene.mMeshes[mesh_index];
    const int offset = static_cast<int>(corners.size());
    const int count = static_cast<int>(mesh.mNumVertices);
    if (count > 0 && mesh.mVertices == nullptr)
      throw InputError("", "mesh " + std::to_string(mesh_index), "mesh has no vertex positions");
    const bool mirrored = transform.topLeftCorner<3, 3>().determinant() < 0;
    for (int i = 0; i < count; ++i) {
      const aiVector3D& p = mesh.mVertices[i];
      const Eigen::Vector3d local(p.x, p.y, p.z);
      const Eigen::Vector3d placed = transform.topLeftCorner<3, 3>() * local + transform.topRightCorner<3, 1>();
      if (!placed.allFinite()) {
        const std::string where = several_meshes ? "mesh " + std::to_string(mesh_index) + ", " : std::string();
        throw InputError("", where + "vertex " + std::to_string(i), "coordinate is NaN or infinite");
      }
      corners.push_back(placed);
    }
    if (mesh.mNumFaces > 0 && mesh.mFaces == nullptr) return;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3 || face.mIndices == nullptr) continue;  // points, lines
      Eigen::Vector3i tri;
      for (int k = 0; k < 3; ++k) {
        const unsigned index = face.mIndices[k];
        if (index >= static_cast<unsigned>(count)) {
          const std::string where = several_meshes ? "mesh " + std::to_string(mesh_index) + ", " : std::string();
          throw InputError("", where + "face " + std::to_string(f),
                           "vertex index " + std::to_string(index) + " out of range (" + std::to_string(count) +
                               " vertices)");
        }
        tri[k] = offset + static_cast<int>(index);
      }
      if (mirrored) std::swap(tri[1], tri[2]);
      faces.push_back(tri);
    }
  };

  if (scene.mRootNode != nullptr) {
    // Depth-first over the node tree, carrying the accumulated transform.
    std::vector<std::pair<const aiNode*, Eigen::Matrix4d>> stack{
        {scene.mRootNode, to_eigen(scene.mRootNode->mTransformation)}};
    std::size_t visited = 0;
    while (!stack.empty()) {
      auto [node, transform] = stack.back();
      stack.pop_back();
      if (++visited > 10'000'000) throw InputError("", "", "scene graph too large");
      for (unsigned i = 0; i < node->mNumMeshes; ++i)
        if (!only || node->mMeshes[i] == *only) add_mesh(node->mMeshes[i], transform);
      for (unsigned c = 0; c < node->mNumChildren; ++c) {
        const aiNode* child = node->mChildren[c];
        if (child != nullptr) stack.emplace_back(child, transform * to_eigen(child->mTransformation));
      }
    }
  } else {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
      if (!only || m == *only) add_mesh(m, Eigen::Matrix4d::Identity());
  }
  if (faces.empty()) throw InputError("", "", "no triangles");

  Mesh out;
  detail::weld_vertices(corners, faces, out.V, out.F);
  return out;
}

bool is_own_format(const std::string& extension) {
  return extension == "obj" || extension == "off" || extension == "ply";
}

/// Reads OBJ, OFF and PLY with our own readers (see load_mesh.h for why); nullopt for other
/// formats.
std::optional<Mesh> read_own_format(const std::string& extension, const std::string& bytes) {
  detail::RawMesh content;
  if (extension == "obj")
    content = detail::read_obj(bytes);
  else if (extension == "off")
    content = detail::read_off(bytes);
  else if (extension == "ply")
    content = detail::read_ply(bytes);
  else
    return std::nullopt;
  if (content.triangles.empty()) throw InputError("", "", "no triangles");
  Mesh out;
  detail::weld_vertices(content.positions, content.triangles, out.V, out.F);
  return out;
}

/// One importer per thread: building one sets up all of Assimp's importers, which costs more
/// than reading a small file.
Assimp::Importer& thread_importer() {
  thread_local Assimp::Importer importer;
  return importer;
}

/// Converts the scene `importer` just read with `convert` (or reports why it could not), then
/// frees it.
template <typename Convert = Mesh (*)(const aiScene&)>
auto read_scene(Assimp::Importer& importer, const aiScene* scene, Convert convert = [](const aiScene& s) {
  return scene_to_mesh(s);
}) {
  struct FreeScene {
    Assimp::Importer& importer;
    ~FreeScene() { importer.FreeScene(); }
  } free_scene{importer};
  if (scene == nullptr) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unreadable or unsupported mesh file";
    throw InputError("", "", why);
  }
  return convert(*scene);
}

/// Each mesh of `scene` that has triangles on its own, named as in the file.
std::vector<NamedMesh> scene_to_meshes(const aiScene& scene) {
  std::vector<NamedMesh> meshes;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (mesh == nullptr || mesh->mNumFaces == 0) continue;
    try {
      meshes.push_back({mesh->mName.C_Str(), scene_to_mesh(scene, m)});
    } catch (const InputError& error) {
      if (error.message() != "no triangles") throw;  // only points or lines, or never placed
    }
  }
  if (meshes.empty()) throw InputError("", "", "no triangles");
  return meshes;
}

}  // namespace

Mesh load_mesh(const std::filesystem::path& path, const MeshLoadOptions& options) {
  try {
    const std::string extension = lower_extension(path.extension().string());
    const std::string bytes = read_input_file(path);
    if (is_own_format(extension)) return *read_own_format(extension, bytes);
    Assimp::Importer& importer = thread_importer();
    if (!detail::looks_like_gltf(extension, bytes))  // from the bytes read: the file is read once
      return read_scene(importer, importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, extension.c_str()));
    // A glTF's buffers may lie in other files, which Assimp reads after the checks.
    detail::check_gltf(bytes, std::filesystem::absolute(path).parent_path(), options.allow_outside_paths);
    return read_scene(importer, importer.ReadFile(path.string(), kImportFlags));
  } catch (const InputError& e) {
    throw e.file().empty() ? e.in_file(path.string()) : e;
  } catch (const std::exception& e) {
    throw InputError(path.string(), "", std::string("could not read mesh: ") + e.what());
  }
}

std::vector<NamedMesh> load_mesh_parts(const std::filesystem::path& path, const MeshLoadOptions& options) {
  try {
    const std::string extension = lower_extension(path.extension().string());
    const std::string bytes = read_input_file(path);
    if (is_own_format(extension)) return {{"", *read_own_format(extension, bytes)}};
    Assimp::Importer& importer = thread_importer();
    if (!detail::looks_like_gltf(extension, bytes))
      return read_scene(importer, importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, extension.c_str()),
                        scene_to_meshes);
    detail::check_gltf(bytes, std::filesystem::absolute(path).parent_path(), options.allow_outside_paths);
    return read_scene(importer, importer.ReadFile(path.string(), kImportFlags), scene_to_meshes);
  } catch (const InputError& e) {
    throw e.file().empty() ? e.in_file(path.string()) : e;
  } catch (const std::exception& e) {
    throw InputError(path.string(), "", std::string("could not read mesh: ") + e.what());
  }
}

Mesh load_mesh_from_memory(const std::string& bytes, const std::string& extension_hint,
                          const MeshLoadOptions& options) {
  if (bytes.empty()) throw InputError("", "", "empty file");
  const std::string hint = lower_extension(extension_hint);
  try {
    if (auto mesh = read_own_format(hint, bytes)) return *mesh;
    // Assimp reads the files a glTF in memory refers to from the working folder.
    if (detail::looks_like_gltf(hint, bytes))
      detail::check_gltf(bytes, std::filesystem::current_path(), options.allow_outside_paths);
    Assimp::Importer& importer = thread_importer();
    return read_scene(importer, importer.ReadFileFromMemory(bytes.data(), bytes.size(), kImportFlags, hint.c_str()));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("", "", std::string("could not read mesh: ") + e.what());
  }
}

}  // namespace reconfig::geometry
