#pragma once
// Exact rational arithmetic for the narrow-phase oracles: positions of linearly moving
// vertices and orientation of four points, with no rounding at all.

#include <gmpxx.h>

#include <Eigen/Core>
#include <array>

namespace reconfig::collision::exact {

using Q3 = std::array<mpq_class, 3>;

/// x0 + t (x1 − x0), exactly.
inline Q3 lerp_exact(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const mpq_class& t) {
  Q3 r;
  for (int i = 0; i < 3; ++i) r[i] = mpq_class(x0[i]) + t * (mpq_class(x1[i]) - mpq_class(x0[i]));
  return r;
}

/// det[b − a, c − a, d − a], exactly: zero iff the four points are coplanar.
inline mpq_class orient_exact(const Q3& a, const Q3& b, const Q3& c, const Q3& d) {
  mpq_class m[3][3];
  for (int i = 0; i < 3; ++i) {
    m[0][i] = b[i] - a[i];
    m[1][i] = c[i] - a[i];
    m[2][i] = d[i] - a[i];
  }
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

}  // namespace reconfig::collision::exact
