#pragma once
/// @file
/// Reading triangle meshes from files (OBJ, STL, PLY, OFF, glTF/GLB and whatever else Assimp reads).

#include <filesystem>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

struct MeshLoadOptions {
  /// Let a glTF's buffer and image URIs lead outside its own folder (absolute paths, `..`).
  bool allow_outside_paths = false;
};

/// Reads the triangle mesh in `path`: OBJ, OFF and PLY with our own readers, every other
/// format (STL, glTF/GLB, and whatever else Assimp reads) with Assimp.
///
/// Polygons are triangulated (ear clipping: concave polygons are fine); every mesh of a
/// multi-mesh scene is placed by its node transforms (a mirroring transform flips the faces so
/// they stay outward) and all are merged into one mesh. Vertices at exactly the same position
/// are welded into one, whatever their normals or texture coordinates, so a closed part stays
/// closed even from formats that store one vertex per face corner (STL, glTF with flat
/// normals). Points and lines are ignored. Faces are kept as they are, degenerate or not:
/// `check_mesh` reports them.
///
/// Vertices no face uses are dropped; the others keep their file order where the format has
/// shared vertices (OBJ, OFF, PLY), and come in order of first use by the faces otherwise
/// (Assimp's importers store one vertex per face corner).
///
/// Precision: OBJ, OFF and PLY coordinates are read exactly (text as the nearest double), so
/// `save_obj` then `load_mesh` gives back the same numbers. Assimp reads coordinates in single
/// precision: for the other formats a loaded coordinate is a `float` (STL stores floats anyway).
///
/// Why our own readers: Assimp 5.2's OFF importer silently drops polygons with more than nine
/// corners and clamps out-of-range or negative indices; its PLY importer loops forever on some
/// truncated headers (found by the fuzz test); its OBJ importer reads floats, not correctly
/// rounded. Ours report bad data with its place (`line <n>`, `header line <n>`, `vertex <i>`,
/// `face <i>`).
///
/// @param path  the file; the format is chosen from its extension, then its content
/// @return the mesh (#V×3 positions, #F×3 triangles with indices in [0, #V))
/// Hostile files are refused before Assimp sees them: only regular files of at most
/// `kMaxInputFileBytes` are read (read_input_file.h); a glTF or GLB must declare no more data
/// than it has, keep its node tree within 256 levels and its buffer and image URIs inside its
/// folder (docs/file-formats.md, "Limits").
///
/// @throws InputError naming `path` if the file is missing or unreadable, the format is unknown
///   or malformed (Assimp's message), there are no triangles, a face refers to a vertex that
///   does not exist (`face <i>`), or a coordinate is NaN or infinite (`vertex <i>`).
Mesh load_mesh(const std::filesystem::path& path, const MeshLoadOptions& options = {});

/// One mesh of a file, with the name the file gives it ("" when none).
struct NamedMesh {
  std::string name;
  Mesh mesh;
};

/// Reads each mesh of `path` on its own, as `load_mesh` reads them all together: a glTF/GLB
/// (or another format Assimp reads) with several meshes gives one per mesh that has triangles
/// (each instance placed by its node transforms; several instances of one mesh stay one mesh);
/// OBJ, OFF, PLY and single-mesh files give one. Same limits and errors as `load_mesh`.
std::vector<NamedMesh> load_mesh_parts(const std::filesystem::path& path, const MeshLoadOptions& options = {});

/// Same as `load_mesh`, from the bytes of a file held in memory (formats whose data is spread
/// over several files, such as glTF with an external .bin, need `load_mesh`).
///
/// @param bytes           the file's content
/// @param extension_hint  the file's extension, with or without the dot ("obj", ".stl", "glb")
/// @throws InputError (with an empty file name) as `load_mesh`
Mesh load_mesh_from_memory(const std::string& bytes, const std::string& extension_hint,
                          const MeshLoadOptions& options = {});

}  // namespace reconfig::geometry
