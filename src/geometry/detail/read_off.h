#pragma once
/// @file
/// Our own reader for the OFF format (internal). Assimp 5.2's OFF importer silently drops
/// polygons with more than 9 corners and clamps out-of-range or negative indices to valid ones;
/// this one reports them, and reads coordinates in double precision.

#include <string>

#include "geometry/detail/raw_mesh.h"

namespace reconfig::geometry::detail {

/// Parses ASCII OFF (header keyword `OFF` with optional ST/C/N prefixes, `#` comments, one
/// vertex per line with extra values such as colors ignored, one polygon per line as a corner
/// count then the indices, trailing colors ignored). Polygons with fewer than 3 corners are
/// skipped; larger ones are triangulated.
/// @throws InputError (empty file name; location `line <n>`) on malformed content, an index out
///   of range, or a non-finite coordinate
RawMesh read_off(const std::string& bytes);

}  // namespace reconfig::geometry::detail
