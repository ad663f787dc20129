#pragma once
/// @file
/// Sculpting the selected part with a swept tool (the sculpt module, Sweepers §5.2): the
/// inspector's Sculpt section (the tool, its size and coating, one stroke by numbers and its
/// Apply button) and the sculpt mode (K): the tool drawn translucent in the viewport,
/// right-drag puts it on the part's surface under the mouse without deforming, left-drag
/// deforms — the tool follows the mouse in the view plane (or turns about the view axis in
/// turn mode), a left-drag on one of its three rings (tool_rings.h) turns it about that
/// ring's axis, the mouse wheel scales it while the button is held. Each stroke (press to
/// release) is one undoable edit of the part's mesh, replaced frame by frame while the
/// collision service re-detects the part's transitions; a refused sub-step stops the stroke
/// at its last good state. The next stroke starts with the tool where the last one left it,
/// as big and as turned. Its own state, drawn by `draw` (like pip_panel.h).

#include <imgui.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>

#include "reconfig/geometry/mesh.h"
#include "reconfig/render/draw_list.h"
#include "reconfig/sculpt/sculpt_mesh.h"
#include "reconfig/sculpt/tool.h"
#include "reconfig/sculpt/tool_motion.h"
#include "reconfig/view/picking.h"
#include "baked_tool_cache.h"
#include "tool_rings.h"

namespace reconfig::studio {

class Studio;

class SculptPanel {
 public:
  /// The tool and a stroke by numbers, in the selected part's rest frame: a tool of `shape`
  /// at `center`, turned by `rotation`, moved by one translation, scaling (about its center)
  /// or rotation (about an axis through its center), mirrored in a coordinate plane if asked.
  struct Settings {
    /// 0 sphere (radius size.x), 1 box (edge lengths), 2 capsule (radius, length), 3 ellipsoid
    /// (semi-axes), 4 another part of the design baked as a tool (`tool_part`, where it is now)
    int shape = 0;
    Eigen::Vector3d size = Eigen::Vector3d::Constant(0.05);
    double coating = 0.05;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    /// The tool's orientation: its own axes turned by this (about its center; a baked part
    /// about the center of its box, from where it is now)
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    int tool_part = -1;  ///< shape 4: the part baked as the tool
    int stroke = 0;      ///< 0 translate, 1 scale, 2 rotate
    Eigen::Vector3d translation = Eigen::Vector3d(0, 0, 0.02);
    double factor = 1.2;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    double degrees = 30;
    int mirror = -1;    ///< −1 none, 0 x = 0, 1 y = 0, 2 z = 0
    double remesh = 0;  ///< > 0: remesh to edges of at most this length (and at least a quarter)
  };
  /// What a left-drag in sculpt mode does.
  enum class DragMode { kMove, kTurn };

  Settings& settings() { return settings_; }
  const Settings& settings() const { return settings_; }

  /// Applies the stroke of `settings()` to the selected part's mesh as one undoable edit
  /// (saved beside the design), the collision service re-detecting the part's transitions.
  /// @return false (the status line says why) with no part selected, bad settings, or a stroke
  ///   the foldover or self-intersection checks refuse
  bool apply_stroke(Studio& studio);

  // ---- sculpt mode ------------------------------------------------------------------------
  /// Turns sculpt mode on (for the selected part; refused with a message without one) or off
  /// (a stroke under way ends as it is). @return whether it is on
  bool set_mode(Studio& studio, bool on);
  bool mode() const { return mode_; }
  DragMode drag_mode = DragMode::kMove;
  /// The viewport's mouse in sculpt mode: right press on the part starts placing the tool,
  /// left press on a ring, the part or the tool starts a stroke, and the drags they start.
  /// Called before the viewport's own handling. @return whether it took the mouse this frame
  bool handle_mouse(Studio& studio, const view::Ray& ray, bool hovered);
  /// The tool, translucent, where it is (in sculpt mode).
  void add_to_draw_list(const Studio& studio, render::DrawList& list) const;
  /// The tool's rings (in sculpt mode, with a tool), about its own axes in the world.
  std::optional<ToolRings> rings(const Studio& studio) const;
  /// The ring drawn under the screen point `at` (ImGui coordinates), if any.
  std::optional<int> ring_at(const Studio& studio, const ImVec2& at) const;
  /// Draws the rings over the viewport's picture (the hovered or dragged one highlighted).
  void draw_rings(const Studio& studio, ImDrawList* draw) const;
  /// The inspector's Sculpt section.
  void draw(Studio& studio);

  /// A stroke is under way (the left button is held in sculpt mode).
  bool stroking() const { return stroke_.has_value(); }
  /// Where the tool's center is in the world now (sculpt mode, a part selected).
  std::optional<Eigen::Vector3d> tool_center(const Studio& studio) const;

 private:
  struct Stroke {
    std::string part = {};      ///< its name: indices may change under a structural undo
    /// The part's mesh as the stroke has made it so far (room to grow, and its index).
    sculpt::SculptMesh sculpted = {};
    sculpt::Tool tool;          ///< in the part's rest frame, where the stroke has moved it
    Eigen::Vector3d tool_origin = Eigen::Vector3d::Zero();  ///< the tool's center in its own frame
    Eigen::Isometry3d to_world = Eigen::Isometry3d::Identity();  ///< the part's placement
    Eigen::Vector3d last_point = Eigen::Vector3d::Zero();  ///< the mouse on the drag plane (world)
    Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();  ///< the view direction (world)
    /// A turning stroke's axis (world): the view direction in turn mode, a ring's axis
    std::optional<Eigen::Vector3d> turn_axis = {};
    std::optional<int> ring = {};       ///< the ring dragged
    Eigen::Vector2d last_mouse = Eigen::Vector2d::Zero();  ///< where the mouse was (screen)
    std::uint64_t live_version = 0;    ///< the design version the stroke's edit made
    bool live = false;                 ///< its edit is applied (replaced by the next move)
    bool stopped = false;              ///< refused: the rest of the drag changes nothing
    int moves = 0, substeps = 0, vertices_moved = 0;
    double least_determinant = 1;
  };

  /// The settings' tool in the part's rest frame and its shape in its own frame, or a message.
  std::optional<sculpt::Tool> make_tool(const Studio& studio, geometry::Mesh* shape, Eigen::Vector3d* origin,
                                        std::string& problem) const;
  /// The ring of `tool_rings` drawn under the screen point `at`, if any.
  static std::optional<int> ring_at(const Studio& studio, const ToolRings& tool_rings, const ImVec2& at);
  /// The selected part's placement now (rest frame → world).
  std::optional<Eigen::Isometry3d> part_to_world(const Studio& studio) const;
  /// Where `ray` first meets the selected part (world), if it does.
  std::optional<Eigen::Vector3d> hit_part(const Studio& studio, const view::Ray& ray) const;
  void place_tool(Studio& studio, const view::Ray& ray);
  /// A stroke from the mouse at `ray`: a turn about `ring`'s axis, or (on the part or the
  /// tool only) a move or a turn as `drag_mode` says. @return whether it started
  bool start_stroke(Studio& studio, const view::Ray& ray, std::optional<int> ring);
  void continue_stroke(Studio& studio, const view::Ray& ray);
  /// The turn the mouse swept round the tool's center since the last frame. @return whether
  ///   the mesh changed
  bool turn_tool(Studio& studio);
  /// One move of the stroke's tool: deforms the stroke's mesh. @return whether the mesh changed
  ///   (false also when refused: the stroke is then stopped)
  bool move_tool(Studio& studio, const sculpt::ToolMotion& motion);
  /// The stroke's mesh as the part's, replacing the stroke's previous edit if still the latest.
  void show_live(Studio& studio);
  void finish_stroke(Studio& studio);
  void draw_mode_controls(Studio& studio);
  /// The tool's rotation as an axis and an angle (the inspector's way, axis_angle.h).
  void draw_rotation_fields();

  Settings settings_;
  /// The tool part baked last (`make_tool` is asked for the tool several times a frame).
  mutable BakedToolCache baked_tool_;
  bool mode_ = false;
  bool placing_ = false;  ///< a right-drag is placing the tool
  std::optional<Stroke> stroke_;
};

}  // namespace reconfig::studio
