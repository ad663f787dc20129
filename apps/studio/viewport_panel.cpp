// The 3D viewport: the scene at the current time, collision boxes, ghosts, the selected part's
// path and the move/rotate gizmo; orbit, pan, zoom, click to select, drag the gizmo to edit.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "panel_window.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/view/ghost_sampling.h"
#include "reconfig/view/picking.h"
#include "resolve_panel.h"
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

void Studio::draw_viewport() {
  const PanelRects rects = current_panel_rects();
  begin_panel("Viewport", rects.viewport_pos, rects.viewport_size, false);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 available = ImGui::GetContentRegionAvail();
  const int width = std::max(static_cast<int>(available.x), 1), height = std::max(static_cast<int>(available.y), 1);
  layout_.viewport_min = origin;
  layout_.viewport_max = {origin.x + width, origin.y + height};
  if (document_ && frame_pending_) frame_all();

  // Input first, so the picture drawn this frame already shows what the mouse did.
  ImGui::InvisibleButton("##viewport", {static_cast<float>(width), static_cast<float>(height)},
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  if (document_) handle_viewport_mouse(origin, width, height);
  render_viewport_image(width, height);
  // The image's rows are bottom-up (GL): flip it with the texture coordinates.
  ImGui::SetCursorScreenPos(origin);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(viewport_image_.texture())),
               {static_cast<float>(width), static_cast<float>(height)}, {0, 1}, {1, 0});
  if (document_) {
    draw_gizmo(ImGui::GetWindowDrawList(), origin, width, height);
    draw_handle_drag(ImGui::GetWindowDrawList(), origin, width, height);
    const scene::Reconfigurable& scene = document_->scene();
    const std::string caption = active_transition_ >= 0
                                    ? fmt::format("{}   t = {:.3f}", scene.transitions[active_transition_].name, time_)
                                    : fmt::format("state {}", scene.states[active_state_].name);
    ImGui::GetWindowDrawList()->AddText({origin.x + 10, origin.y + 8}, IM_COL32(40, 40, 50, 255), caption.c_str());
  } else {
    ImGui::GetWindowDrawList()->AddText({origin.x + 20, origin.y + 20}, IM_COL32(60, 60, 70, 255),
                                        "No design open: File > Open (Ctrl+O), or reconfig-studio SCENE.json");
  }
  ImGui::End();
}

bool Studio::ViewportInputs::operator==(const ViewportInputs& other) const {
  return std::tie(document, version, snapshot, transition, state, time, selected, width, height, camera, preview,
                  ghosts, ghost_count, ghost_spacing, intervals, detailed, hint, envelope) ==
         std::tie(other.document, other.version, other.snapshot, other.transition, other.state, other.time,
                  other.selected, other.width, other.height, other.camera, other.preview, other.ghosts,
                  other.ghost_count, other.ghost_spacing, other.intervals, other.detailed, other.hint,
                  other.envelope);
}

void Studio::render_viewport_image(int width, int height) {
  // Redraw only when what the picture shows changed (or its boxes pulse).
  ViewportInputs inputs{document_.get(), document_ ? document_->version() : 0, collisions().get(),
                        active_transition_, active_state_, time_, selected_part_, width, height,
                        {camera_.target.x(), camera_.target.y(), camera_.target.z(), camera_.distance, camera_.yaw,
                         camera_.pitch, camera_.fov_y, camera_.near_plane, camera_.far_plane},
                        {}, show_ghosts, ghost_count, ghost_spacing, show_intervals};
  const bool moving = playing_ || gizmo_drag_ || viewport_dragging_ || timeline().dragging() ||
                     ImGui::IsMouseDragging(ImGuiMouseButton_Right) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle);
  inputs.detailed = !moving;
  if (const auto& hint = resolution_hint()) inputs.hint = {hint->part, static_cast<std::int64_t>(hint->version)};
  inputs.envelope = shaping_.envelope_shown();
  if (drag_preview_)
    inputs.preview = {drag_preview_->translation.x(), drag_preview_->translation.y(), drag_preview_->translation.z(),
                      drag_preview_->rotation.w(), drag_preview_->rotation.x(), drag_preview_->rotation.y(),
                      drag_preview_->rotation.z()};
  if (!viewport_pulsing_ && last_viewport_inputs_ && *last_viewport_inputs_ == inputs) return;
  last_viewport_inputs_ = inputs;
  viewport_image_.resize(width, height);
  viewport_image_.bind();
  render::DrawList list;
  if (document_) {
    const scene::Reconfigurable& scene = document_->scene();
    render::SceneDrawRequest request;
    std::vector<bool> clearance_boxes;  // per box of the request: a clearance interval's (amber)
    request.transition = active_transition_;
    request.time = time_;
    request.state = active_state_;
    if (selected_part_ >= 0) request.selected = {selected_part_};
    if (drag_preview_ && selected_part_ >= 0) request.pose_overrides = {{selected_part_, *drag_preview_}};
    // While things move, big designs are drawn coarser (and in full detail once they stop).
    if (moving) {
      request.resident_meshes = document_->moving_meshes();
    } else {
      request.resident_meshes = document_->part_meshes();
      request.solid_parts = document_->solid_parts();
    }
    if (active_transition_ >= 0) {
      if (show_ghosts) {
        view::GhostRequest ghosts;
        ghosts.current = time_;
        ghosts.count = ghost_count;
        ghosts.spacing = ghost_spacing;
        request.ghosts = view::ghost_samples(ghosts);
      }
      // Boxes of the short (one-frame) intervals that overlap the current time.
      if (const auto snapshot = collisions(); snapshot && show_intervals)
        for (const auto& transition : snapshot->transitions)
          if (transition.transition == active_transition_)
            for (const auto& interval : transition.frames)
              if (interval.t0 <= time_ + 1e-9 && time_ <= interval.t1 + 1e-9) {
                request.boxes.push_back(interval.box);
                clearance_boxes.push_back(interval.clearance);
              }
    }
    list = render::scene_draw_list(scene, request);
    for (std::size_t i = 0; i < clearance_boxes.size() && i < list.boxes.size(); ++i)
      if (clearance_boxes[i]) list.boxes[i].color = {1.0f, 0.75f, 0.0f};  // amber, as on the timeline
    list.seconds = seconds_;
    viewport_pulsing_ = !list.boxes.empty();
    // The selected part's path: where its pivot goes over the transition.
    if (active_transition_ >= 0 && selected_part_ >= 0) {
      render::LineItem path;
      path.color = {0.15f, 0.35f, 0.85f, 1.0f};
      const Eigen::Vector3d pivot = scene.parts[selected_part_].center;
      for (int i = 0; i <= 120; ++i)
        path.points.push_back(scene.pose_at(active_transition_, selected_part_, i / 120.0).translation + pivot);
      list.lines.push_back(std::move(path));
      // Its translation keys and the Bézier handles that shape the motion (dragged here, or
      // edited in the inspector).
      if (const scene::KeyframedTrack* keyed = selected_keyframed_track()) {
        render::LineItem handles;
        handles.strip = false;
        handles.color = {0.95f, 0.55f, 0.1f, 1.0f};
        const double tick = 0.01 * camera_.distance;
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
    }
  }
  resolve().add_hint_arrows(*this, list);
  shaping_.add_to_draw_list(*this, list);
  renderer_.draw(list, camera_, width, height);
  render::RenderTarget::unbind();
}

view::Ray Studio::mouse_ray(const ImVec2& origin, int width, int height) const {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  return view::ray_from_pixel(camera_, width, height, mouse.x - origin.x, mouse.y - origin.y);
}

int Studio::pick_part(const view::Ray& ray) const {
  const scene::Reconfigurable& scene = document_->scene();
  int best = -1;
  double best_s = INFINITY;
  for (int part = 0; part < static_cast<int>(scene.parts.size()); ++part) {
    const Eigen::MatrixX3d V = active_transition_ >= 0 ? scene.posed_vertices(active_transition_, part, time_)
                                                       : scene.posed_vertices_in_state(active_state_, part);
    const auto hit = view::ray_mesh(ray, V, scene.parts[part].mesh.F);
    if (hit && hit->s < best_s) {
      best_s = hit->s;
      best = part;
    }
  }
  return best;
}

void Studio::handle_viewport_mouse(const ImVec2& origin, int width, int height) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const view::Ray ray = mouse_ray(origin, width, height);
  const Eigen::Vector2d mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);

  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    const GizmoHandle handle = gizmo_ ? gizmo_->hit(camera_, width, height, mouse) : GizmoHandle::kNone;
    const scene::KeyframedTrack* keyed = selected_keyframed_track();
    const Eigen::Vector3d pivot = keyed ? document_->scene().parts[selected_part_].center : Eigen::Vector3d();
    std::optional<HandleRef> bezier;
    if (handle == GizmoHandle::kNone && keyed) bezier = hit_handle(keyed->translation, pivot, camera_, width, height, mouse);
    if (handle != GizmoHandle::kNone && selected_pose()) {
      gizmo_drag_ = GizmoDrag{handle, gizmo_->center, *selected_pose(), ray};
    } else if (bezier) {
      const motion::TranslationKey& key = keyed->translation[bezier->key];
      handle_drag_ = HandleDrag{*bezier, key, handle_end(key, pivot, bezier->out), camera_.forward(), ray};
      selected_key_ = KeyRef{scene::KeyKind::kTranslation, bezier->key};
    } else {
      viewport_dragging_ = true;
    }
  }
  if (handle_drag_) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      const motion::TranslationKey key = handle_drag_->key_for(ray);
      const int index = handle_drag_->handle.key;
      handle_drag_.reset();
      const scene::Reconfigurable& scene = document_->scene();
      if (io.MouseDragMaxDistanceSqr[0] > 4)  // a click on a handle only selects its key
        execute(scene::set_translation_key(scene.transitions[active_transition_].name, scene.parts[selected_part_].name,
                                           index, key));
    }
    return;
  }
  if (gizmo_drag_) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      drag_preview_ = gizmo_drag_->pose_for(ray);
    } else {
      const motion::Pose pose = gizmo_drag_->pose_for(ray);
      gizmo_drag_.reset();
      drag_preview_.reset();
      if (io.MouseDragMaxDistanceSqr[0] > 4) apply_pose(pose);  // a click on a handle changes nothing
    }
    return;
  }
  if (viewport_dragging_) {
    const double world_per_pixel = 2 * camera_.distance * std::tan(camera_.fov_y / 2) / height;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 2)) {
      if (io.KeyShift) camera_.pan(-io.MouseDelta.x * world_per_pixel, io.MouseDelta.y * world_per_pixel);
      else camera_.orbit(-io.MouseDelta.x * kOrbitPerPixel, io.MouseDelta.y * kOrbitPerPixel);
    }
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
      viewport_dragging_ = false;
      if (io.MouseDragMaxDistanceSqr[0] <= 9) select_part(pick_part(ray));
    }
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 2))
    camera_.orbit(-io.MouseDelta.x * kOrbitPerPixel, io.MouseDelta.y * kOrbitPerPixel);
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 2)) {
    const double world_per_pixel = 2 * camera_.distance * std::tan(camera_.fov_y / 2) / height;
    camera_.pan(-io.MouseDelta.x * world_per_pixel, io.MouseDelta.y * world_per_pixel);
  }
  if (hovered && io.MouseWheel != 0) camera_.zoom(std::pow(0.88, io.MouseWheel));
}

bool Studio::selected_part_collides_now() const {
  const auto snapshot = collisions();
  if (!snapshot || selected_part_ < 0 || !show_intervals) return false;
  for (const auto& transition : snapshot->transitions)
    if (transition.transition == active_transition_)
      for (const auto& interval : transition.frames)
        if (interval.t0 <= time_ + 1e-9 && time_ <= interval.t1 + 1e-9 &&
            std::find(interval.parts.begin(), interval.parts.end(), selected_part_) != interval.parts.end())
          return true;
  return false;
}

void Studio::draw_gizmo(ImDrawList* draw, const ImVec2& origin, int width, int height) {
  gizmo_.reset();
  const std::optional<motion::Pose> pose = drag_preview_ ? drag_preview_ : selected_pose();
  if (!pose) return;
  const Eigen::Vector3d pivot = document_->scene().parts[selected_part_].center + pose->translation;
  gizmo_ = Gizmo::sized_for(camera_, height, gizmo_drag_ ? gizmo_drag_->center : pivot);
  const ImGuiIO& io = ImGui::GetIO();
  const GizmoHandle hovered =
      gizmo_drag_    ? gizmo_drag_->handle
      : handle_drag_ ? GizmoHandle::kNone  // a Bézier handle has the mouse
                     : gizmo_->hit(camera_, width, height, {io.MousePos.x - origin.x, io.MousePos.y - origin.y});
  const bool faded = selected_part_collides_now();
  for (const GizmoHandle handle : {GizmoHandle::kRotateX, GizmoHandle::kRotateY, GizmoHandle::kRotateZ,
                                   GizmoHandle::kMoveX, GizmoHandle::kMoveY, GizmoHandle::kMoveZ}) {
    std::vector<ImVec2> points;
    for (const Eigen::Vector3d& point : gizmo_->shape(handle))
      if (const auto projected = view::project_to_pixel(camera_, width, height, point))
        points.push_back({origin.x + static_cast<float>(projected->pixel.x()),
                          origin.y + static_cast<float>(projected->pixel.y())});
    if (points.size() < 2) continue;
    const ImU32 color = handle_color(handle, handle == hovered, faded);
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, is_rotation(handle) ? 2.0f : 3.0f);
    if (!is_rotation(handle)) {
      // Arrow head: a triangle at the tip, pointing along the projected axis.
      const ImVec2 a = points.front(), b = points.back();
      const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
      if (length > 1) {
        const float ux = dx / length, uy = dy / length;
        draw->AddTriangleFilled({b.x + 10 * ux, b.y + 10 * uy}, {b.x - 5 * uy, b.y + 5 * ux},
                                {b.x + 5 * uy, b.y - 5 * ux}, color);
      }
    }
  }
}

void Studio::draw_handle_drag(ImDrawList* draw, const ImVec2& origin, int width, int height) const {
  const scene::KeyframedTrack* keyed = handle_drag_ ? selected_keyframed_track() : nullptr;
  if (!keyed) return;
  std::vector<motion::TranslationKey> keys = keyed->translation;
  const motion::TranslationKey& key = keys[handle_drag_->handle.key] = handle_drag_->key_for(mouse_ray(origin, width, height));
  const Eigen::Vector3d pivot = document_->scene().parts[selected_part_].center;
  const auto screen = [&](const Eigen::Vector3d& point) -> std::optional<ImVec2> {
    const auto p = view::project_to_pixel(camera_, width, height, point);
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
