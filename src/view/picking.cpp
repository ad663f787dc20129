#include "reconfig/view/picking.h"

#include <cmath>

namespace reconfig::view {

Ray ray_from_pixel(const Camera& camera, int width, int height, double x, double y) {
  const double aspect = static_cast<double>(width) / height;
  const double ndc_x = 2 * x / width - 1;
  const double ndc_y = 1 - 2 * y / height;
  const double tan_half = std::tan(camera.fov_y / 2);
  const Eigen::Vector3d direction =
      camera.forward() + ndc_x * tan_half * aspect * camera.right() + ndc_y * tan_half * camera.up();
  return {camera.eye(), direction.normalized()};
}

std::optional<Projection> project_to_pixel(const Camera& camera, int width, int height, const Eigen::Vector3d& point) {
  const Eigen::Vector3d offset = point - camera.eye();
  const double depth = offset.dot(camera.forward());
  if (depth <= 0) return std::nullopt;
  const double aspect = static_cast<double>(width) / height;
  const double tan_half = std::tan(camera.fov_y / 2);
  const double ndc_x = offset.dot(camera.right()) / (depth * tan_half * aspect);
  const double ndc_y = offset.dot(camera.up()) / (depth * tan_half);
  return Projection{{(ndc_x + 1) * width / 2, (1 - ndc_y) * height / 2}, depth};
}

std::optional<double> ray_plane(const Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  const double facing = ray.direction.dot(normal);
  if (std::abs(facing) < 1e-6 * normal.norm()) return std::nullopt;
  const double s = (point - ray.origin).dot(normal) / facing;
  if (!(s >= 0)) return std::nullopt;
  return s;
}

std::optional<double> ray_triangle(const Ray& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  const double scale = e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) return std::nullopt;  // parallel or degenerate
  const double inv = 1 / det;
  const Eigen::Vector3d to_origin = ray.origin - a;
  const double u = to_origin.dot(p) * inv;
  if (u < 0 || u > 1) return std::nullopt;
  const Eigen::Vector3d q = to_origin.cross(e1);
  const double v = ray.direction.dot(q) * inv;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double s = e2.dot(q) * inv;
  if (s < 0) return std::nullopt;
  return s;
}

std::optional<MeshHit> ray_mesh(const Ray& ray, const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
  std::optional<MeshHit> best;
  for (int f = 0; f < F.rows(); ++f) {
    const auto s = ray_triangle(ray, V.row(F(f, 0)).transpose(), V.row(F(f, 1)).transpose(), V.row(F(f, 2)).transpose());
    if (s && (!best || *s < best->s)) best = MeshHit{f, *s};
  }
  return best;
}

}  // namespace reconfig::view
