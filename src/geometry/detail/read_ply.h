#pragma once
/// @file
/// Our own reader for the PLY format (internal). Assimp 5.2's PLY importer loops forever on
/// some truncated headers (found by the loader fuzz test); this one checks every read.

#include <string>

#include "geometry/detail/raw_mesh.h"

namespace reconfig::geometry::detail {

/// Parses PLY (ascii, binary_little_endian, binary_big_endian): the `vertex` element's x, y, z
/// (any numeric type) and the `face` element's `vertex_indices` (or `vertex_index`) list;
/// other elements and properties are skipped. Polygons with fewer than 3 corners are skipped;
/// larger ones are triangulated.
/// @throws InputError (empty file name; location `header line <n>`, `vertex <i>` or
///   `face <i>`) on a malformed header or data, an index out of range, a non-finite coordinate
RawMesh read_ply(const std::string& bytes);

}  // namespace reconfig::geometry::detail
