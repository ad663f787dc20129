#pragma once
/// @file
/// The 3D viewport: the scene at the current time, collision boxes, ghosts, the selected part's
/// path and the move/rotate gizmo; orbit, pan, zoom, click to select, drag the gizmo or a
/// Bézier handle to edit. Its own state (its picture and what it was drawn from, the drags in
/// progress, the gizmo as drawn), drawn by `draw` (like pip_panel.h); the camera, time and
/// selection are the studio's.

#include <imgui.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "gizmo.h"
#include "handle_drag.h"
#include "reconfig/render/draw_list.h"
#include "reconfig/render/render_target.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/view/picking.h"

namespace reconfig::collision {
struct CollisionSnapshot;
}

namespace reconfig::studio {

class Document;
class Studio;

class ViewportPanel {
 public:
  void draw(Studio& studio);
  /// The gizmo as drawn this frame (for the selected part), if any.
  const std::optional<Gizmo>& gizmo() const { return gizmo_; }
  /// Drops the gizmo's drag (a new design was opened).
  void cancel_drags();

 private:
  /// Everything the picture depends on; an unchanged picture is not drawn again.
  struct Inputs {
    const Document* document = nullptr;
    std::uint64_t version = 0;
    const collision::CollisionSnapshot* snapshot = nullptr;
    int transition = -1, state = 0;
    double time = 0;
    int selected = -1, width = 0, height = 0;
    std::array<double, 9> camera{};
    std::array<double, 7> preview{};
    bool ghosts = false;
    int ghost_count = 0;
    float ghost_spacing = 0;
    bool intervals = false;
    bool detailed = true;  ///< full meshes (false: the coarse ones drawn while things move)
    std::array<std::int64_t, 2> hint{-1, 0};  ///< the hint's part and design version (arrows)
    bool envelope = false;                     ///< the swept envelope is shown
    std::uint64_t shaping = 0;                 ///< ShapingPanel::overlay_revision()
    bool operator==(const Inputs& other) const;
  };
  /// Something moves (playing, a drag, orbiting): big designs are drawn coarser.
  bool moving(Studio& studio) const;
  Inputs inputs(Studio& studio, int width, int height, bool moving) const;
  void render_image(Studio& studio, int width, int height);
  /// The scene at the current time, with ghosts and the boxes of the short (one-frame)
  /// intervals there; `clearance_boxes` says which boxes are a clearance interval's.
  render::SceneDrawRequest draw_request(const Studio& studio, bool moving, std::vector<bool>& clearance_boxes) const;
  /// The selected part's path, its translation keys and their Bézier handles.
  void add_selected_path(const Studio& studio, render::DrawList& list) const;

  void handle_mouse(Studio& studio, const ImVec2& origin, int width, int height);
  /// A left click: grabs a gizmo handle or a Bézier handle, else starts orbiting.
  void start_drag(Studio& studio, const view::Ray& ray, const Eigen::Vector2d& mouse, int width, int height);
  void update_handle_drag(Studio& studio, const view::Ray& ray);
  void update_gizmo_drag(Studio& studio, const view::Ray& ray);
  /// Orbit (left or right drag), pan (shift+left or middle drag), zoom (wheel), select (click).
  void move_camera(Studio& studio, const view::Ray& ray, bool hovered, int height);
  view::Ray mouse_ray(const Studio& studio, const ImVec2& origin, int width, int height) const;
  int pick_part(const Studio& studio, const view::Ray& ray) const;

  void draw_gizmo(Studio& studio, ImDrawList* draw, const ImVec2& origin, int width, int height);
  /// Whether a collision box of the selected part is shown at the current time (the gizmo
  /// then fades, so it does not hide the box).
  bool selected_part_collides_now(const Studio& studio) const;
  /// The handle being dragged at its new place, over the picture (which shows the old one).
  void draw_handle_drag(const Studio& studio, ImDrawList* draw, const ImVec2& origin, int width, int height) const;

  render::RenderTarget image_;
  std::optional<Inputs> last_inputs_;
  bool pulsing_ = false;  ///< collision boxes on screen: redraw every frame
  std::optional<GizmoDrag> gizmo_drag_;
  std::optional<HandleDrag> handle_drag_;
  std::optional<motion::Pose> drag_preview_;  ///< the selected part's pose as the gizmo drags it
  std::optional<Gizmo> gizmo_;
  bool orbiting_ = false;  ///< a left drag of the view (orbit, or pan with shift)
};

}  // namespace reconfig::studio
