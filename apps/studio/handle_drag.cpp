#include "handle_drag.h"

#include <cmath>

namespace reconfig::studio {
namespace {

/// Where the ray crosses the plane through `point` with normal `normal`, if it does at a usable
/// angle.
std::optional<Eigen::Vector3d> plane_crossing(const view::Ray& ray, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  const double facing = ray.direction.dot(normal);
  if (std::abs(facing) < 1e-6) return std::nullopt;
  return ray.at((point - ray.origin).dot(normal) / facing);
}

}  // namespace

Eigen::Vector3d handle_end(const motion::TranslationKey& key, const Eigen::Vector3d& pivot, bool out) {
  return pivot + (out ? key.out : key.in);
}

std::vector<HandleRef> shaping_handles(const std::vector<motion::TranslationKey>& keys) {
  std::vector<HandleRef> handles;
  const int n = static_cast<int>(keys.size());
  for (int key = 0; key < n; ++key) {
    if (key > 0) handles.push_back({key, false});
    if (key + 1 < n) handles.push_back({key, true});
  }
  return handles;
}

std::optional<HandleRef> hit_handle(const std::vector<motion::TranslationKey>& keys, const Eigen::Vector3d& pivot,
                                    const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                                    double tolerance) {
  std::optional<HandleRef> best;
  double best_distance = tolerance;
  for (const HandleRef& handle : shaping_handles(keys)) {
    const auto projected = view::project_to_pixel(camera, width, height, handle_end(keys[handle.key], pivot, handle.out));
    if (!projected) continue;
    const double distance = (projected->pixel - mouse).norm();
    if (distance <= best_distance) {
      best_distance = distance;
      best = handle;
    }
  }
  return best;
}

motion::TranslationKey HandleDrag::key_for(const view::Ray& ray) const {
  const auto from = plane_crossing(start_ray, start_end, normal), to = plane_crossing(ray, start_end, normal);
  motion::TranslationKey key = start_key;
  if (!from || !to) return key;
  (handle.out ? key.out : key.in) += *to - *from;
  return key;
}

}  // namespace reconfig::studio
