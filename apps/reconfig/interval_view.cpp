#include "interval_view.h"

namespace reconfig::cli {

render::BestView interval_best_view(render::OcclusionCounter& counter, const scene::Reconfigurable& scene,
                                    int transition, const collision::CollisionInterval& interval, double time) {
  return render::best_view(counter, scene, render::interval_view_request(scene, transition, interval, time));
}

view::Camera picture_camera(const render::BestView& view, const Eigen::AlignedBox3d& scene_bounds) {
  view::Camera camera = view.camera;
  camera.fov_y = 1.2;
  camera.fit_planes(scene_bounds);
  return camera;
}

nlohmann::ordered_json view_json(const render::BestView& view) {
  const auto array = [](const Eigen::Vector3d& v) { return nlohmann::ordered_json::array({v.x(), v.y(), v.z()}); };
  return {{"eye", array(view.camera.eye())},
          {"center", array(view.camera.target)},
          {"up", array(view.camera.up())},
          {"visible_fraction", view.pixels.visible_fraction()}};
}

}  // namespace reconfig::cli
