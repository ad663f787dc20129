#pragma once
/// @file
/// The 3×3 determinant det[x, y, z] = x · (y × z), evaluated in one fixed order (the
/// coplanarity cubic's error analysis assumes this one).

namespace reconfig::collision::detail {

inline double det3(const double x[3], const double y[3], const double z[3]) {
  return x[0] * (y[1] * z[2] - y[2] * z[1]) + x[1] * (y[2] * z[0] - y[0] * z[2]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
}

}  // namespace reconfig::collision::detail
