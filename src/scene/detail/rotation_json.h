#pragma once
// A rotation as a person types it into a scene file: a unit quaternion `[w, x, y, z]`, an
// angle about an axis `{"axis": [x, y, z], "degrees": d}`, or Euler angles about fixed axes
// in a stated order `{"euler_degrees": [a, b, c], "order": "xyz"}` (docs/file-formats.md).

#include <Eigen/Geometry>

#include "scene/detail/json_cursor.h"

namespace reconfig::scene::detail {

/// The unit quaternion `c` describes, in any of the three forms; errors name the element at
/// fault (`….rotation.axis: the axis must not be zero`).
Eigen::Quaterniond read_rotation(const JsonCursor& c);

}  // namespace reconfig::scene::detail
