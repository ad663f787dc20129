// The jump to a collision interval's best view (V) and the pictures of the picture-in-picture:
// occlusion counts over candidate views (render/best_view.h), a short camera glide.

#include <fmt/format.h>

#include "side_effects.h"
#include "studio.h"
#include "reconfig/render/best_view.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/view/scene_bounds.h"

namespace reconfig::studio {

view::Camera Studio::best_view_camera(int transition, const collision::CollisionInterval& interval, double time) {
  if (!occlusion_counter_) occlusion_counter_ = std::make_unique<render::OcclusionCounter>();
  render::BestViewRequest request = render::interval_view_request(document_->scene(), transition, interval, time);
  request.fov_y = camera_.fov_y;
  view::Camera camera = render::best_view(*occlusion_counter_, document_->scene(), request).camera;
  camera.fit_planes(view::scene_bounds_at(document_->scene(), transition, time));  // the whole design, not just X
  return camera;
}

void Studio::glide_to(const view::Camera& camera) { camera_glide_ = CameraGlide{camera_, camera, seconds_, 0.4}; }

bool Studio::jump_to_best_view() {
  const auto snapshot = collisions();
  if (!snapshot || active_transition_ < 0) {
    set_status("Best view: open a transition with collisions first");
    return false;
  }
  for (const collision::TransitionSnapshot& transition : snapshot->transitions) {
    if (transition.transition != active_transition_) continue;
    const int focus = focused_interval(transition.intervals, time_, selected_part_);
    if (focus < 0) break;
    const collision::CollisionInterval& interval = transition.intervals[focus];
    if (time_ < interval.t0 || time_ > interval.t1) set_time(0.5 * (interval.t0 + interval.t1));
    glide_to(best_view_camera(active_transition_, interval, time_));
    std::string parts;
    for (int part : interval.parts) parts += (parts.empty() ? "" : " × ") + document_->scene().parts[part].name;
    set_status(fmt::format("Best view of {} (t = {:.3f} to {:.3f})", parts, interval.t0, interval.t1));
    return true;
  }
  set_status("Best view: no collision interval in this transition");
  return false;
}

void Studio::render_view(render::RenderTarget& target, const view::Camera& camera, int transition, double time,
                         const std::vector<Eigen::AlignedBox3d>& boxes, int width, int height) {
  target.resize(width, height);
  target.bind();
  render::DrawList list;
  if (document_) {
    render::SceneDrawRequest request;
    request.transition = transition;
    request.time = time;
    request.boxes = boxes;
    request.resident_meshes = document_->part_meshes();
    request.solid_parts = document_->solid_parts();
    list = render::scene_draw_list(document_->scene(), request);
    list.seconds = seconds_;
  }
  renderer_.draw(list, camera, width, height);
  render::RenderTarget::unbind();
}

}  // namespace reconfig::studio
