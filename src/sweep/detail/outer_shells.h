#pragma once
/// @file
/// Dropping the cavities of a closed mesh: the connected components that enclose a negative
/// volume (inward-facing shells inside another one).

#include "reconfig/geometry/mesh.h"

namespace reconfig::sweep::detail {

/// `mesh` without its inward-facing components (faces joined through shared vertices) and
/// without the vertices they used.
/// @param mesh      #V×3, #F×3, closed components
/// @param removed   out: how many components were dropped
geometry::Mesh outer_shells(const geometry::Mesh& mesh, int& removed);

}  // namespace reconfig::sweep::detail
