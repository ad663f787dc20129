#pragma once
/// @file
/// Our own reader for Wavefront OBJ geometry (internal): exact double coordinates, so that
/// `save_obj` followed by `load_mesh` gives back the same numbers (Assimp reads floats with a
/// parser that is not correctly rounded).

#include <string>

#include "geometry/detail/raw_mesh.h"

namespace reconfig::geometry::detail {

/// Parses the geometry of an OBJ file: `v x y z` (extra values such as w or a color are
/// ignored) and `f` polygons whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn`, with 1-based
/// or negative (relative) indices. Lines ending in a backslash continue on the next line;
/// everything else (`vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, ...) is ignored.
/// Polygons are triangulated.
/// @throws InputError (empty file name; location `line <n>`) on a malformed vertex or face, an
///   index that is zero or out of range, or a non-finite coordinate (`line <n>, vertex <i>`)
RawMesh read_obj(const std::string& bytes);

}  // namespace reconfig::geometry::detail
