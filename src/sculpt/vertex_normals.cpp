#include "reconfig/sculpt/vertex_normals.h"

#include <algorithm>
#include <cmath>

namespace reconfig::sculpt {

Eigen::MatrixX3d vertex_normals(const geometry::Mesh& mesh) {
  Eigen::MatrixX3d N = Eigen::MatrixX3d::Zero(mesh.vertex_count(), 3);
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.norm() == 0) continue;
    const Eigen::Vector3d unit = normal.normalized();
    const Eigen::Vector3d corners[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d u = (corners[(i + 1) % 3] - corners[i]).normalized();
      const Eigen::Vector3d v = (corners[(i + 2) % 3] - corners[i]).normalized();
      N.row(mesh.F(f, i)) += std::acos(std::clamp(u.dot(v), -1.0, 1.0)) * unit.transpose();
    }
  }
  for (int i = 0; i < N.rows(); ++i)
    if (N.row(i).norm() > 0) N.row(i).normalize();
  return N;
}

}  // namespace reconfig::sculpt
