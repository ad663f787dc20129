#include "reconfig/geometry/mass_properties.h"

#include <cmath>
#include <string>

#include "reconfig/common/input_error.h"

namespace reconfig::geometry {

MassProperties mass_properties(const Mesh& mesh) {
  MassProperties out;
  const int n = mesh.vertex_count();
  for (int f = 0; f < mesh.face_count(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k);
      if (v < 0 || v >= n) throw InputError("", "face " + std::to_string(f), "vertex index out of range");
      out.bounds.extend(mesh.V.row(v).transpose());
    }
  }
  if (mesh.face_count() == 0) {
    out.center_is_surface_centroid = true;
    return out;
  }
  const Eigen::Vector3d reference = out.bounds.center();

  // Every term is relative to `reference`, which keeps the sums well conditioned.
  double six_volume = 0;
  Eigen::Vector3d weighted_tet_centroid = Eigen::Vector3d::Zero();  // Σ 6·vol_i · (a+b+c)/4
  double double_area = 0;
  Eigen::Vector3d weighted_face_centroid = Eigen::Vector3d::Zero();  // Σ 2·area_i · (a+b+c)/3
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose() - reference;
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1)).transpose() - reference;
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2)).transpose() - reference;
    const double det = a.dot(b.cross(c));
    six_volume += det;
    weighted_tet_centroid += det * (a + b + c);
    const double twice_area = (b - a).cross(c - a).norm();
    double_area += twice_area;
    weighted_face_centroid += twice_area * (a + b + c);
  }
  out.volume = six_volume / 6;
  out.surface_area = double_area / 2;
  const double diagonal = out.bounds.diagonal().norm();
  if (std::abs(out.volume) > 1e-12 * diagonal * diagonal * diagonal && std::isfinite(out.volume)) {
    out.center_of_mass = reference + weighted_tet_centroid / (4 * six_volume);
  } else {
    out.center_is_surface_centroid = true;
    out.center_of_mass = double_area > 0 ? Eigen::Vector3d(reference + weighted_face_centroid / (3 * double_area))
                                         : reference;
  }
  return out;
}

}  // namespace reconfig::geometry
