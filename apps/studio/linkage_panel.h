#pragma once
/// @file
/// The linkage panel (LinkEdit §4–§5, Fig. 1): a 2D view of the open transition's linkage drive,
/// or of a linkage file opened alone. Joints, links, the crank's reachable arc and the tracking
/// points' curves are drawn at the motor angle of the current time (the studio's timeline
/// plays and scrubs it; a linkage opened alone has its own slider and Play). Dragging a joint
/// runs LinkEdit live (linkage_editor.h) and releasing it is one undoable edit: of the drive
/// (scene::set_linkage_drive, so the driven parts follow and their collisions are detected
/// again), or of the linkage opened alone (its own undo). Dragging a tracking curve bends its
/// target curve (soft selection) and fits the linkage to it. An enclosure box, keep-curve
/// checkboxes, and the motion's problems in red. Its own state, drawn by `draw`.

#include <imgui.h>

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "linkage_editor.h"

namespace reconfig::studio {

class Studio;

/// Whether `file` is a JSON document of format "reconfig-linkage" (not whether it is valid).
bool is_linkage_file(const std::filesystem::path& file);

class LinkagePanel {
 public:
  /// Shows the drive of transition `transition` (which becomes the open one). @return false
  /// (the status line says why) if it has no drive
  bool open_drive(Studio& studio, int transition);
  /// Opens a "reconfig-linkage" file alone. A file that cannot be read or fails its checks is
  /// a status message, and whatever was shown stays. @return success
  bool open_file(Studio& studio, const std::filesystem::path& file);
  /// File > Open linkage...: asks for a path (the panel's own dialog).
  void request_open_dialog();
  /// Hides the panel (a linkage opened alone is closed).
  void close();
  /// The panel's Close button: a linkage opened alone with unsaved edits is closed only when
  /// pressed a second time (the first says so in the status line).
  void close_unless_unsaved(Studio& studio);
  /// A new design was opened: a linkage opened alone closes; the panel shows the first
  /// transition's drive if it has one.
  void document_opened(Studio& studio);

  bool shown() const { return shown_; }
  /// A linkage file is open alone (not a transition's drive).
  bool lone() const { return shown_ && lone_file_.has_value(); }
  /// A linkage opened alone has edits not saved yet.
  bool lone_modified() const { return lone() && lone_modified_; }
  /// The transition whose drive is shown, or −1 (none, or a linkage opened alone).
  int transition(const Studio& studio) const;

  /// Draws the panel (over the viewport's left part; over viewport and timeline when alone).
  void draw(Studio& studio);

  /// The editor of the shown linkage (kept in step with the design each frame).
  LinkageEditor& editor() { return editor_; }
  const LinkageEditor& editor() const { return editor_; }
  /// The motor angle shown (radians, unwrapped).
  double angle(const Studio& studio) const;
  /// A linkage opened alone: show it at motor angle `angle` (radians).
  void set_lone_angle(double angle) { lone_angle_ = angle; }
  /// Joint positions at the angle shown. @return false if none can be drawn
  bool joints_now(const Studio& studio, Eigen::Matrix2Xd& X) const;
  /// The tracking points' curves when the panel was opened on this linkage (for checks).
  const std::vector<std::vector<Eigen::Vector2d>>& opened_curves() const { return opened_curves_; }
  /// The motor angles (radians) those curves are sampled at.
  const std::vector<double>& opened_angles() const { return opened_angles_; }
  /// The joint and target (linkage units) of the last joint drag released, if any.
  const std::optional<std::pair<int, Eigen::Vector2d>>& last_drag() const { return last_drag_; }
  /// Soft-selection radius of curve drags (linkage units).
  double soft_radius = 0;

  /// Screen position of a linkage point in this frame's canvas, and back.
  ImVec2 screen_point(const Eigen::Vector2d& p) const;
  Eigen::Vector2d linkage_point(ImVec2 s) const;

  /// Applies an edit: the drive's new linkage as one undoable scene command labelled `label`,
  /// or the new state of a linkage opened alone. A refused outcome changes nothing and its
  /// reason goes to the status line. @return success
  bool apply(Studio& studio, const LinkageEditOutcome& outcome, const std::string& label);
  /// Runs LinkEdit towards the targets and into the enclosure and applies it.
  bool fit(Studio& studio);

  /// A linkage opened alone: its undo and redo, and saving it (as `file`, or where it came from).
  bool undo(Studio& studio);
  bool redo(Studio& studio);
  bool save(Studio& studio, const std::optional<std::filesystem::path>& file = std::nullopt);

 private:
  struct JointDrag {
    int joint = -1;
    double angle = 0;
    Eigen::Vector2d start = Eigen::Vector2d::Zero(), target = Eigen::Vector2d::Zero();
    ImVec2 press{0, 0};
    std::optional<LinkageEditOutcome> preview;
  };
  struct CurveDrag {
    int point = -1, index = -1;
    ImVec2 press{0, 0};
    std::vector<Eigen::Vector2d> base;  ///< the target (or curve) when the drag started
  };

  /// Loads the shown transition's drive into the editor when the design changed.
  void sync(Studio& studio);
  void load(linkage::Linkage linkage);
  /// Remembers the curves of the linkage just opened (opened_curves).
  void remember_opened();
  void fit_view();
  void draw_controls(Studio& studio);
  /// The row that scales, turns and moves a tracking point's target curve (LinkEdit's global
  /// transformation mode), then fits.
  void draw_transform_row(Studio& studio);
  void draw_canvas(Studio& studio, ImVec2 size);
  void handle_mouse(Studio& studio, const Eigen::Matrix2Xd& X);
  void finish_joint_drag(Studio& studio);
  void finish_curve_drag(Studio& studio);
  void draw_linkage(ImDrawList* draw, const linkage::Linkage& linkage, const Eigen::Matrix2Xd& X, ImU32 color,
                    bool joints) const;
  void draw_crank_range(ImDrawList* draw, const Eigen::Matrix2Xd& X) const;
  void draw_curves(ImDrawList* draw) const;
  void draw_open_dialog(Studio& studio);

  bool shown_ = false;
  std::optional<std::filesystem::path> lone_file_;
  LinkageEditor editor_;
  std::uint64_t synced_version_ = 0;
  int synced_transition_ = -1;
  std::vector<std::vector<Eigen::Vector2d>> opened_curves_;
  std::vector<double> opened_angles_;
  std::vector<std::vector<Eigen::Vector2d>> drawn_curves_;  ///< fine curves of the tracking points
  // A linkage opened alone.
  std::vector<linkage::Linkage> undo_, redo_;
  double lone_angle_ = 0;
  bool lone_playing_ = false;
  bool lone_modified_ = false;
  bool discard_armed_ = false;  ///< Close was pressed once on unsaved edits: the next one discards
  // The canvas: linkage point c is drawn at canvas_center_, `scale_` pixels per unit, y up.
  Eigen::Vector2d view_center_ = Eigen::Vector2d::Zero();
  double view_size_ = 1;  ///< linkage units the canvas's shorter side shows
  ImVec2 canvas_min_{0, 0}, canvas_max_{0, 0};
  std::optional<JointDrag> joint_drag_;
  std::optional<CurveDrag> curve_drag_;
  std::optional<std::pair<int, Eigen::Vector2d>> last_drag_;
  float enclosure_draft_[4] = {0, 0, 0, 0};
  /// The target transform row: which tracking point, and scale, degrees, tx, ty.
  int transform_point_ = 0;
  float transform_draft_[4] = {1, 0, 0, 0};
  bool show_open_dialog_ = false;
  std::string open_path_;
};

}  // namespace reconfig::studio
