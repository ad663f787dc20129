#pragma once
/// @file
/// Writing triangle meshes to OBJ and STL files.
///
/// Both writers are atomic: they write `<path>.tmp` and rename it over `path` once it is
/// complete, so a reader never sees a half-written file and a failed write leaves the old
/// file in place.

#include <filesystem>
#include <string>
#include <vector>

#include "reconfig/geometry/mesh.h"

namespace reconfig::geometry {

/// Writes `mesh` as a Wavefront OBJ (`v x y z` with 17 significant digits, `f a b c` 1-based):
/// positions round-trip exactly through a double-precision reader.
/// @param path  the file to write (replaced if it exists)
/// @param mesh  #V×3 positions, #F×3 triangles
/// @throws InputError naming `path` if the file cannot be written, or (nothing written) if a
///   face index is out of range (`face <i>`) or a coordinate is not finite (`vertex <i>`)
void save_obj(const std::filesystem::path& path, const Mesh& mesh);

/// One object of a multi-object OBJ file: a name (`o <name>`) and its mesh.
struct ObjObject {
  std::string name;
  Mesh mesh;
};

/// Writes `objects` as one Wavefront OBJ with an `o <name>` line before each object's `v` and
/// `f` lines, so that Blender and MeshLab show them as separate objects; whitespace and control
/// characters in a name become `_` (an empty name `unnamed`). Vertices are numbered through the
/// file; positions are written as by `save_obj(path, mesh)`.
/// @throws InputError as `save_obj(path, mesh)`, for the first object at fault
void save_obj(const std::filesystem::path& path, const std::vector<ObjObject>& objects);

/// Writes `mesh` as an STL, binary (little-endian, 80-byte header) or ASCII ("solid reconfig").
/// STL stores one triangle after another with single-precision coordinates and no shared
/// vertices: loading it back welds equal positions, so vertex order and index numbering change,
/// and positions are rounded to `float`. Each facet's normal is the unit normal of the
/// triangle (zero for a degenerate one).
/// @param path    the file to write (replaced if it exists)
/// @param mesh    #V×3 positions, #F×3 triangles
/// @param binary  binary STL if true, ASCII otherwise
/// @throws InputError naming `path` as `save_obj`
void save_stl(const std::filesystem::path& path, const Mesh& mesh, bool binary = true);

}  // namespace reconfig::geometry
