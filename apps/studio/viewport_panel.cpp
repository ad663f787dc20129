#include "viewport_panel.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "panel_window.h"
#include "reconfig/view/ghost_sampling.h"
#include "resolve_panel.h"
#include "shaping_panel.h"
#include "studio.h"
#include "timeline_panel.h"

namespace reconfig::studio {
namespace {

/// `faded`: see-through, so the collision box the gizmo would cover shows (the hot handle
/// stays opaque).
ImU32 handle_color(GizmoHandle handle, bool hot, bool faded) {
  if (hot) return IM_COL32(250, 200, 30, 255);
  const Eigen::Vector3d axis = handle_axis(handle);
  return IM_COL32(static_cast<int>(40 + 190 * axis.x()), static_cast<int>(40 + 150 * axis.y()),
                  static_cast<int>(40 + 200 * axis.z()), faded ? 90 : 255);
}

}  // namespace

void ViewportPanel::cancel_drags() {
  gizmo_drag_.reset();
  drag_preview_.reset();
}

void ViewportPanel::draw(Studio& studio) {
  const PanelRects rects = current_panel_rects();
  begin_panel("Viewport", rects.viewport_pos, rects.viewport_size, false);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const int width = std::max(static_cast<int>(available.x), 1), height = std::max(static_cast<int>(available.y), 1);
  studio.layout_.viewport_min = origin;
  studio.layout_.viewport_max = {origin.x + width, origin.y + height};
  const Document* document = studio.document();
  if (document && studio.frame_pending_) studio.frame_all();

  // Input first, so the picture drawn this frame already shows what the mouse did.
  ImGui::InvisibleButton("##viewport", {static_cast<float>(width), static_cast<float>(height)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  if (document) handle_mouse(studio, origin, width, height);
  render_image(studio, width, height);
  // The image's rows are bottom-up (GL): flip it with the texture coordinates.
  ImGui::SetCursorScreenPos(origin);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(image_.texture())),
               {static_cast<float>(width), static_cast<float>(height)}, {0, 1}, {1, 0});
  ImDrawList* draw = ImGui::GetWindowDrawList();
  if (document) {
    draw_gizmo(studio, draw, origin, width, height);
    studio.sculpt().draw_rings(studio, draw);  // in sculpt mode, instead of the gizmo
    draw_handle_drag(studio, draw, origin, width, height);
    const scene::Reconfigurable& scene = document->scene();
    const int transition = studio.active_transition();
    const std::string caption = transition >= 0
                                    ? fmt::format("{}   t = {:.3f}", scene.transitions[transition].name, studio.time())
                                    : fmt::format("state {}", scene.states[studio.active_state_].name);
    draw->AddText({origin.x + 10, origin.y + 8}, IM_COL32(40, 40, 50, 255), caption.c_str());
  } else {
    draw->AddText({origin.x + 20, origin.y + 20}, IM_COL32(60, 60, 70, 255),
                  "No design open: File > Open (Ctrl+O), or reconfig-studio SCENE.json");
  }
  ImGui::End();
}

bool ViewportPanel::Inputs::operator==(const Inputs& other) const {
  return std::tie(document, version, snapshot, transition, state, time, selected, width, height, camera, preview,
                  ghosts, ghost_count, ghost_spacing, intervals, detailed, hint, envelope, shaping) ==
         std::tie(other.document, other.version, other.snapshot, other.transition, other.state, other.time,
                  other.selected, other.width, other.height, other.camera, other.preview, other.ghosts,
                  other.ghost_count, other.ghost_spacing, other.intervals, other.detailed, other.hint,
                  other.envelope, other.shaping);
}

bool ViewportPanel::moving(Studio& studio) const {
  return studio.playing() || gizmo_drag_ || orbiting_ || studio.timeline().dragging() ||
         ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle);
}

ViewportPanel::Inputs ViewportPanel::inputs(Studio& studio, int width, int height, bool moving) const {
  const Document* document = studio.document();
  const view::Camera& camera = studio.camera();
  Inputs inputs{document, document ? document->version() : 0, studio.collisions().get(),
                studio.active_transition(), studio.active_state_, studio.time(), studio.selected_part(), width, height,
                {camera.target.x(), camera.target.y(), camera.target.z(), camera.distance, camera.yaw, camera.pitch,
                 camera.fov_y, camera.near_plane, camera.far_plane},
                {}, studio.show_ghosts, studio.ghost_count, studio.ghost_spacing, studio.show_intervals};
  inputs.detailed = !moving;
  if (const auto& hint = studio.resolution_hint()) inputs.hint = {hint->part, static_cast<std::int64_t>(hint->version)};
  inputs.envelope = studio.shaping().envelope_shown();
  inputs.shaping = studio.shaping().overlay_revision();
  if (drag_preview_)
    inputs.preview = {drag_preview_->translation.x(), drag_preview_->translation.y(), drag_preview_->translation.z(),
                      drag_preview_->rotation.w(), drag_preview_->rotation.x(), drag_preview_->rotation.y(),
                      drag_preview_->rotation.z()};
  return inputs;
}

void ViewportPanel::render_image(Studio& studio, int width, int height) {
  // Redraw only when what the picture shows changed (or its boxes pulse).
  const bool now_moving = moving(studio);
  const Inputs now = inputs(studio, width, height, now_moving);
  if (!pulsing_ && last_inputs_ && *last_inputs_ == now) return;
  last_inputs_ = now;
  image_.resize(width, height);
  image_.bind();
  render::DrawList list;
  if (studio.document()) {
    std::vector<bool> clearance_boxes;  // per box of the request: a clearance interval's (amber)
    const render::SceneDrawRequest request = draw_request(studio, now_moving, clearance_boxes);
    list = render::scene_draw_list(studio.document()->scene(), request);
    for (std::size_t i = 0; i < clearance_boxes.size() && i < list.boxes.size(); ++i)
      if (clearance_boxes[i]) list.boxes[i].color = {1.0f, 0.75f, 0.0f};  // amber, as on the timeline
    list.seconds = studio.seconds_;
    pulsing_ = !list.boxes.empty() || studio.sculpt().mode();  // the sculpt tool follows the mouse
    add_selected_path(studio, list);
  }
  studio.resolve().add_hint_arrows(studio, list);
  studio.shaping().add_to_draw_list(studio, list);
  studio.sculpt().add_to_draw_list(studio, list);
  studio.renderer_.draw(list, studio.camera(), width, height);
  render::RenderTarget::unbind();
}

render::SceneDrawRequest ViewportPanel::draw_request(const Studio& studio, bool moving,
                                                     std::vector<bool>& clearance_boxes) const {
  const Document& document = *studio.document();
  const int transition = studio.active_transition(), selected = studio.selected_part();
  const double time = studio.time();
  render::SceneDrawRequest request;
  request.transition = transition;
  request.time = time;
  request.state = studio.active_state_;
  if (selected >= 0) request.selected = {selected};
  if (drag_preview_ && selected >= 0) request.pose_overrides = {{selected, *drag_preview_}};
  // While things move, big designs are drawn coarser (and in full detail once they stop).
  if (moving) {
    request.resident_meshes = document.moving_meshes();
  } else {
    request.resident_meshes = document.part_meshes();
    request.solid_parts = document.solid_parts();
  }
  if (transition < 0) return request;
  if (studio.show_ghosts) {
    view::GhostRequest ghosts;
    ghosts.current = time;
    ghosts.count = studio.ghost_count;
    ghosts.spacing = studio.ghost_spacing;
    request.ghosts = view::ghost_samples(ghosts);
  }
  // Boxes of the short (one-frame) intervals that overlap the current time.
  if (const auto snapshot = studio.collisions(); snapshot && studio.show_intervals)
    for (const auto& shown : snapshot->transitions)
      if (shown.transition == transition)
        for (const auto& interval : shown.frames)
          if (interval.t0 <= time + 1e-9 && time <= interval.t1 + 1e-9) {
            request.boxes.push_back(interval.box);
            clearance_boxes.push_back(interval.clearance);
          }
  return request;
}

void ViewportPanel::add_selected_path(const Studio& studio, render::DrawList& list) const {
  const int transition = studio.active_transition(), selected = studio.selected_part();
  if (transition < 0 || selected < 0) return;
  // The selected part's path: where its pivot goes over the transition.
  const scene::Reconfigurable& scene = studio.document()->scene();
  render::LineItem path;
  path.color = {0.15f, 0.35f, 0.85f, 1.0f};
  const Eigen::Vector3d pivot = scene.parts[selected].center;
  for (int i = 0; i <= 120; ++i)
    path.points.push_back(scene.pose_at(transition, selected, i / 120.0).translation + pivot);
  list.lines.push_back(std::move(path));
  // Its translation keys and the Bézier handles that shape the motion (dragged here, or
  // edited in the inspector).
  const scene::KeyframedTrack* keyed = studio.selected_keyframed_track();
  if (!keyed) return;
  render::LineItem handles;
  handles.strip = false;
  handles.color = {0.95f, 0.55f, 0.1f, 1.0f};
  const double tick = 0.01 * studio.camera_.distance;
  for (const HandleRef& handle : shaping_handles(keyed->translation)) {
    const motion::TranslationKey& key = keyed->translation[handle.key];
    handles.points.insert(handles.points.end(), {pivot + key.point, handle_end(key, pivot, handle.out)});
  }
  for (const motion::TranslationKey& key : keyed->translation)
    for (int axis = 0; axis < 3; ++axis) {
      handles.points.push_back(pivot + key.point - tick * Eigen::Vector3d::Unit(axis));
      handles.points.push_back(pivot + key.point + tick * Eigen::Vector3d::Unit(axis));
    }
  list.lines.push_back(std::move(handles));
}

view::Ray ViewportPanel::mouse_ray(const Studio& studio, const ImVec2& origin, int width, int height) const {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  return view::ray_from_pixel(studio.camera_, width, height, mouse.x - origin.x, mouse.y - origin.y);
}

int ViewportPanel::pick_part(const Studio& studio, const view::Ray& ray) const {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const int transition = studio.active_transition();
  int best = -1;
  double best_s = INFINITY;
  for (int part = 0; part < static_cast<int>(scene.parts.size()); ++part) {
    const Eigen::MatrixX3d V = transition >= 0 ? scene.posed_vertices(transition, part, studio.time())
                                               : scene.posed_vertices_in_state(studio.active_state_, part);
    const auto hit = view::ray_mesh(ray, V, scene.parts[part].mesh.F);
    if (hit && hit->s < best_s) {
      best_s = hit->s;
      best = part;
    }
  }
  return best;
}

void ViewportPanel::handle_mouse(Studio& studio, const ImVec2& origin, int width, int height) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const view::Ray ray = mouse_ray(studio, origin, width, height);
  const Eigen::Vector2d mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
  if (studio.sculpt().handle_mouse(studio, ray, hovered)) return;  // sculpt mode's drags (sculpt_panel.h)
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) start_drag(studio, ray, mouse, width, height);
  if (handle_drag_) return update_handle_drag(studio, ray);
  if (gizmo_drag_) return update_gizmo_drag(studio, ray);
  move_camera(studio, ray, hovered, height);
}

void ViewportPanel::start_drag(Studio& studio, const view::Ray& ray, const Eigen::Vector2d& mouse, int width,
                               int height) {
  const view::Camera& camera = studio.camera_;
  const GizmoHandle handle = gizmo_ ? gizmo_->hit(camera, width, height, mouse) : GizmoHandle::kNone;
  const scene::KeyframedTrack* keyed = studio.selected_keyframed_track();
  const Eigen::Vector3d pivot =
      keyed ? studio.document()->scene().parts[studio.selected_part()].center : Eigen::Vector3d();
  std::optional<HandleRef> bezier;
  if (handle == GizmoHandle::kNone && keyed)
    bezier = hit_handle(keyed->translation, pivot, camera, width, height, mouse);
  if (handle != GizmoHandle::kNone && studio.selected_pose()) {
    gizmo_drag_ = GizmoDrag{handle, gizmo_->center, *studio.selected_pose(), ray};
  } else if (bezier) {
    const motion::TranslationKey& key = keyed->translation[bezier->key];
    handle_drag_ = HandleDrag{*bezier, key, handle_end(key, pivot, bezier->out), camera.forward(), ray};
    studio.selected_key_ = KeyRef{scene::KeyKind::kTranslation, bezier->key};
  } else {
    orbiting_ = true;
  }
}

void ViewportPanel::update_handle_drag(Studio& studio, const view::Ray& ray) {
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
  const motion::TranslationKey key = handle_drag_->key_for(ray);
  const int index = handle_drag_->handle.key;
  handle_drag_.reset();
  const scene::Reconfigurable& scene = studio.document()->scene();
  if (ImGui::GetIO().MouseDragMaxDistanceSqr[0] > 4)  // a click on a handle only selects its key
    studio.execute(scene::set_translation_key(scene.transitions[studio.active_transition()].name,
                                              scene.parts[studio.selected_part()].name, index, key));
}

void ViewportPanel::update_gizmo_drag(Studio& studio, const view::Ray& ray) {
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    drag_preview_ = gizmo_drag_->pose_for(ray);
    return;
  }
  const motion::Pose pose = gizmo_drag_->pose_for(ray);
  gizmo_drag_.reset();
  drag_preview_.reset();
  if (ImGui::GetIO().MouseDragMaxDistanceSqr[0] > 4) studio.apply_pose(pose);  // a click on a handle changes nothing
}

void ViewportPanel::move_camera(Studio& studio, const view::Ray& ray, bool hovered, int height) {
  const ImGuiIO& io = ImGui::GetIO();
  view::Camera& camera = studio.camera_;
  const double world_per_pixel = 2 * camera.distance * std::tan(camera.fov_y / 2) / height;
  if (orbiting_) {
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2)) {
      if (io.KeyShift) camera.pan(-io.MouseDelta.x * world_per_pixel, io.MouseDelta.y * world_per_pixel);
      else camera.orbit(-io.MouseDelta.x * Studio::kOrbitPerPixel, io.MouseDelta.y * Studio::kOrbitPerPixel);
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      orbiting_ = false;
      if (io.MouseDragMaxDistanceSqr[0] <= 9) studio.select_part(pick_part(studio, ray));
    }
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 2))
    camera.orbit(-io.MouseDelta.x * Studio::kOrbitPerPixel, io.MouseDelta.y * Studio::kOrbitPerPixel);
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 2))
    camera.pan(-io.MouseDelta.x * world_per_pixel, io.MouseDelta.y * world_per_pixel);
  if (hovered && io.MouseWheel != 0) camera.zoom(std::pow(0.88, io.MouseWheel));
}

bool ViewportPanel::selected_part_collides_now(const Studio& studio) const {
  const auto snapshot = studio.collisions();
  const int selected = studio.selected_part();
  const double time = studio.time();
  if (!snapshot || selected < 0 || !studio.show_intervals) return false;
  for (const auto& transition : snapshot->transitions)
    if (transition.transition == studio.active_transition())
      for (const auto& interval : transition.frames)
        if (interval.t0 <= time + 1e-9 && time <= interval.t1 + 1e-9 &&
            std::find(interval.parts.begin(), interval.parts.end(), selected) != interval.parts.end())
          return true;
  return false;
}

void ViewportPanel::draw_gizmo(Studio& studio, ImDrawList* draw, const ImVec2& origin, int width, int height) {
  gizmo_.reset();
  const std::optional<motion::Pose> pose = drag_preview_ ? drag_preview_ : studio.selected_pose();
  if (!pose || studio.sculpt().mode()) return;  // in sculpt mode the left button sculpts
  const view::Camera& camera = studio.camera_;
  const Eigen::Vector3d pivot = studio.document()->scene().parts[studio.selected_part()].center + pose->translation;
  gizmo_ = Gizmo::sized_for(camera, height, gizmo_drag_ ? gizmo_drag_->center : pivot);
  const ImGuiIO& io = ImGui::GetIO();
  const GizmoHandle hovered =
      gizmo_drag_    ? gizmo_drag_->handle
      : handle_drag_ ? GizmoHandle::kNone  // a Bézier handle has the mouse
                     : gizmo_->hit(camera, width, height, {io.MousePos.x - origin.x, io.MousePos.y - origin.y});
  const bool faded = selected_part_collides_now(studio);
  for (const GizmoHandle handle : {GizmoHandle::kRotateX, GizmoHandle::kRotateY, GizmoHandle::kRotateZ,
                                   GizmoHandle::kMoveX, GizmoHandle::kMoveY, GizmoHandle::kMoveZ}) {
    std::vector<ImVec2> points;
    for (const Eigen::Vector3d& point : gizmo_->shape(handle))
      if (const auto projected = view::project_to_pixel(camera, width, height, point))
        points.push_back({origin.x + static_cast<float>(projected->pixel.x()),
                          origin.y + static_cast<float>(projected->pixel.y())});
    if (points.size() < 2) continue;
    const ImU32 color = handle_color(handle, handle == hovered, faded);
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, is_rotation(handle) ? 2.0f : 3.0f);
    if (is_rotation(handle)) continue;
    // Arrow head: a triangle at the tip, pointing along the projected axis.
    const ImVec2 a = points.front(), b = points.back();
    const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
    if (length <= 1) continue;
    const float ux = dx / length, uy = dy / length;
    draw->AddTriangleFilled({b.x + 10 * ux, b.y + 10 * uy}, {b.x - 5 * uy, b.y + 5 * ux}, {b.x + 5 * uy, b.y - 5 * ux},
                            color);
  }
}

void ViewportPanel::draw_handle_drag(const Studio& studio, ImDrawList* draw, const ImVec2& origin, int width,
                                     int height) const {
  const scene::KeyframedTrack* keyed = handle_drag_ ? studio.selected_keyframed_track() : nullptr;
  if (!keyed) return;
  const view::Camera& camera = studio.camera_;
  std::vector<motion::TranslationKey> keys = keyed->translation;
  const motion::TranslationKey& key = keys[handle_drag_->handle.key] =
      handle_drag_->key_for(mouse_ray(studio, origin, width, height));
  const Eigen::Vector3d pivot = studio.document()->scene().parts[studio.selected_part()].center;
  const auto screen = [&](const Eigen::Vector3d& point) -> std::optional<ImVec2> {
    const auto p = view::project_to_pixel(camera, width, height, point);
    if (!p) return std::nullopt;
    return ImVec2(origin.x + static_cast<float>(p->pixel.x()), origin.y + static_cast<float>(p->pixel.y()));
  };
  // The path as it would become (the picture under it still shows the old one), and the handle.
  const ImU32 blue = IM_COL32(40, 90, 220, 255), orange = IM_COL32(242, 140, 25, 255);
  const motion::BezierTranslationTrack path(keys);
  std::vector<ImVec2> points;
  for (int i = 0; i <= 120; ++i)
    if (const auto point = screen(pivot + path.evaluate(i / 120.0))) points.push_back(*point);
  if (points.size() > 1) draw->AddPolyline(points.data(), static_cast<int>(points.size()), blue, 0, 2.0f);
  const auto from = screen(pivot + key.point), to = screen(handle_end(key, pivot, handle_drag_->handle.out));
  if (!from || !to) return;
  draw->AddLine(*from, *to, orange, 2.0f);
  draw->AddCircleFilled(*to, 4.0f, orange);
}

}  // namespace reconfig::studio
