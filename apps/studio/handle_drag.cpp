#include "handle_drag.h"

namespace reconfig::studio {
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
  const auto from = view::ray_plane(start_ray, start_end, normal), to = view::ray_plane(ray, start_end, normal);
  motion::TranslationKey key = start_key;
  if (!from || !to) return key;
  (handle.out ? key.out : key.in) += ray.at(*to) - start_ray.at(*from);
  return key;
}

}  // namespace reconfig::studio
