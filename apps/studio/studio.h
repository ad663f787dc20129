#pragma once
/// @file
/// The studio's UI: one object that owns the open document and everything the panels share
/// (open transitions, current time, selection, camera, status, layout), builds one ImGui frame
/// at a time, and turns what the user does into scene commands. Each panel is an object of its
/// own holding the state only it uses, with a `draw(Studio&)` (timeline_panel.h, status_bar.h,
/// viewport_panel.h, ...); the studio holds them apart (Studio::Panels, in studio.cpp), so this
/// header includes none of theirs but the PIP's, linkage's and shaping's. Scripts and tests drive
/// the same actions and read the same layout.

#include <imgui.h>

#include <Eigen/Core>
#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "authoring_dialog.h"
#include "camera_glide.h"
#include "document.h"
#include "gizmo.h"
#include "hint_view.h"
#include "linkage_panel.h"
#include "pip_panel.h"
#include "sculpt_panel.h"
#include "shaping_panel.h"
#include "reconfig/render/occlusion_counter.h"
#include "reconfig/render/render_target.h"
#include "reconfig/render/renderer.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/transition_edits.h"
#include "reconfig/view/camera.h"

namespace reconfig::studio {

class AuthoringMenus;
class CollisionSettingsWindow;
class InspectorPanel;
class ResolvePanel;
class StateGraphPanel;
class StatusBar;
class TimelinePanel;
class ViewportPanel;

/// A key of the selected part's track on the timeline.
struct KeyRef {
  scene::KeyKind kind = scene::KeyKind::kTranslation;
  int index = 0;
  bool operator==(const KeyRef&) const = default;
};

/// Where things are on screen this frame (pixels, ImGui's coordinates: origin top-left).
struct Layout {
  ImVec2 viewport_min{0, 0}, viewport_max{0, 0};  ///< the 3D image
  ImVec2 scrub_min{0, 0}, scrub_max{0, 0};        ///< the timeline's time strip
  ImVec2 graph_min{0, 0}, graph_max{0, 0};        ///< the state graph canvas
  float translation_row_y = 0, rotation_row_y = 0;  ///< key rows' centers
  float bands_row_y = 0;                             ///< collision bands' center
};

/// Collision service settings for an editor: detection leaves one core to the UI and runs at a
/// lower priority, so frames keep coming while it works.
collision::CollisionServiceOptions editor_collision_options();

struct StudioOptions {
  std::chrono::milliseconds autosave_interval{3000};
  double play_speed = 0.25;  ///< transition time per second while playing
  collision::CollisionServiceOptions collisions = editor_collision_options();
  scene::SceneLoadOptions load;  ///< `--allow-outside-paths`
  /// A hint whose parts have more triangles than this is computed in the background (building
  /// their shapes and sampling their contours takes a while) and shown when it is ready.
  int background_hint_triangles = 20000;
};

class Studio {
  friend class ShapingPanel;  // its status messages
  friend class SculptPanel;   // its status messages and the time it bakes a tool part at

 public:
  /// Needs the GL context current (the renderer and viewport image live in it).
  explicit Studio(StudioOptions options = {});
  ~Studio();

  // ---- documents -------------------------------------------------------------------------
  /// Opens a scene; on a bad file shows the error (and keeps what was open). If the file has
  /// an autosave newer than itself, asks whether to recover it; so it does when the file is
  /// corrupt or gone but an autosave is there (and then returns true: the autosave is offered).
  bool open(const std::filesystem::path& file);
  /// The file whose autosave is offered for recovery ("" if none).
  const std::filesystem::path& recovery_candidate() const { return recovery_candidate_; }
  /// Opens the offered autosave (the Recover button). @return success
  bool recover_autosave();
  /// Saves atomically; reports failures in the status line. @return success
  bool save();
  bool save_as(const std::filesystem::path& file);
  Document* document() { return document_.get(); }
  const Document* document() const { return document_.get(); }
  const StudioOptions& options() const { return options_; }

  // ---- authoring a design (authoring.cpp) -----------------------------------------------
  /// Starts an empty design that will be saved as `file` (one state, "start"); what was open
  /// is closed (unsaved edits of it stay in its autosave). @return success
  bool new_design(const std::filesystem::path& file);
  /// Imports mesh files as new parts, one undoable step: OBJ, STL, PLY, OFF, glTF/GLB (a file
  /// with several meshes gives one part per mesh, whose geometry is then saved beside the
  /// design). Each part is named after its file (or glTF mesh), made unique; the mesh checks'
  /// warnings (open, non-manifold, self-intersecting) go to the status line. A file that cannot
  /// be read refuses the whole import, the design untouched. @return success
  bool import_meshes(const std::vector<std::filesystem::path>& files);
  /// Replaces the geometry of part `part` with the mesh in `file`, keeping its pivot and poses.
  bool replace_part_mesh_from(int part, const std::filesystem::path& file);
  /// Adds a state named `name` holding the pose every part has in the viewport now.
  bool add_state_from_view(const std::string& name);
  /// Shows state `state` (no transition open): what clicking its node does.
  void show_state(int state);
  /// Adds a transition between states `from` and `to` with a default choreography and opens
  /// it; `name` "" picks "FROM_to_TO" (made unique).
  bool add_transition_between(int from, int to, scene::Choreography choreography, std::string name = "");
  /// Screen position of state `state`'s node in the state graph.
  std::optional<ImVec2> graph_state_point(int state) const;
  /// Opens an authoring dialog (what the menu items do) / performs what it asks for (its OK
  /// button), for tests. @return success; a refusal is in the status line
  void open_authoring_dialog(AuthoringDialog dialog);
  const std::optional<AuthoringDialog>& authoring_dialog() const;
  bool accept_authoring_dialog(const AuthoringDialog& dialog);

  // ---- one frame -------------------------------------------------------------------------
  /// Builds the whole UI for one frame (call between ImGui::NewFrame and ImGui::Render) and
  /// draws the 3D viewport into its image. `now` drives playback, pulsing boxes and autosave.
  void frame(std::chrono::steady_clock::time_point now);
  /// True once the user chose File > Quit (or confirmed closing the window).
  bool quit_requested() const { return quit_; }
  /// While a linkage opened alone has unsaved edits, opening `file` (or starting a new design
  /// as it) is refused with a message. @return whether it was refused
  bool refuse_while_linkage_unsaved(const std::filesystem::path& file);
  /// The window's close button: quits at once when nothing is unsaved, else asks.
  void request_close();
  /// Quits without saving (the question's Discard): the unsaved edits and their autosave go.
  void discard_and_quit();

  // ---- actions (what clicks and keys do; scripts call them too) --------------------------
  void open_transition(int transition);
  void close_transition(int transition);
  void set_time(double t);
  void step(int frames);
  void toggle_play();
  void select_part(int part);
  /// Places the selected part at `pose` at the current time (a keyframe, or the state pose
  /// at t = 0 / 1). @return success (the refusal goes to the status line)
  bool apply_pose(const motion::Pose& pose);
  /// Inserts translation and rotation keys for the selected part at the current time.
  bool insert_key();
  /// Removes the selected inner key.
  bool delete_selected_key();
  /// Moves key `key` of the selected part to time `t` (kept between its neighbours).
  bool move_key_time(KeyRef key, double t);
  bool undo();
  bool redo();
  void frame_all();
  /// Executes a scene command as one undoable step; refusals go to the status line.
  bool execute(std::unique_ptr<scene::Command> command);
  /// How collisions are detected (tolerance, k-DOP family, box grid, frame, conservative
  /// mode). With a design open they are saved with it, as one undoable edit, and detection
  /// starts over; else they are the defaults for designs opened later without settings of
  /// their own. Settings out of range are refused (the reason goes to the status line).
  /// @return success
  bool set_detector_options(const collision::DetectorOptions& options);
  /// Those of the open design (the studio's with the design's own), else the studio's.
  const collision::DetectorOptions& detector_options() const;
  /// Opens the Collisions > Settings window (edits apply with its Apply button).
  void show_collision_settings();
  /// The resolution hint (H) for the selected part: how each of its keys in the open
  /// transition should move to lower the energy of its collision intervals there. Shown as
  /// yellow arrows at the keys and in the inspector, with a slider along the steepest one.
  /// @return false (with the reason in the status line) when there is nothing to hint
  bool request_hint();
  /// Moves the hinted element `amount` along its hint from where it was when the hint was
  /// given (scene units; radians for a rotation; time for a key time). While `live`, each call
  /// replaces the previous one's edit (collisions update as it slides); the last call of a
  /// slide is one undoable edit. @return success
  bool slide_along_hint(double amount, bool live = false);
  /// Starts automatic resolution of the open transition in the background (key times may move
  /// when `move_times`, the transition's states when `move_states`: every transition through a
  /// moved state follows); the result arrives as one undoable edit. @return it started
  bool start_auto_resolve(bool move_times = true, bool move_states = false);
  /// Cancels a running automatic resolution (nothing is changed).
  void cancel_auto_resolve();
  bool auto_resolving() const;
  /// A hint is being computed in the background (see StudioOptions::background_hint_triangles).
  bool hint_pending() const;
  /// The resolution hint on screen (hint_view.h).
  const std::optional<HintView>& resolution_hint() const;
  /// Sculpting the selected part (sculpt_panel.h); the settings and stroke by numbers
  /// forwarded for scripts and tests.
  SculptPanel& sculpt() { return sculpt_; }
  using SculptSettings = SculptPanel::Settings;
  SculptSettings& sculpt_settings() { return sculpt_.settings(); }
  bool sculpt_selected_part() { return sculpt_.apply_stroke(*this); }
  /// The best view (V, reconfigurables §4.3) of the collision interval being worked on (of the
  /// selected part, under the current time, else the nearest): the camera glides there, and the
  /// time moves into the interval when it is outside. @return false when there is none
  bool jump_to_best_view();
  /// The camera (this viewport's field of view) that shows `interval` of `transition` best at
  /// `time`, by the occlusion counts of render/best_view.h (best_view_action.cpp).
  view::Camera best_view_camera(int transition, const collision::CollisionInterval& interval, double time);
  /// Draws the design at `time` of `transition` seen by `camera` into `target` (width × height),
  /// with `boxes`: the picture-in-picture's image.
  void render_view(render::RenderTarget& target, const view::Camera& camera, int transition, double time,
                   const std::vector<Eigen::AlignedBox3d>& boxes, int width, int height);
  /// The camera glides to `camera` (0.4 s).
  void glide_to(const view::Camera& camera);
  /// The picture-in-picture panel (pip_panel.h).
  PipPanel& pip() { return pip_; }
  const PipPanel& pip() const { return pip_; }
  /// The linkage panel (linkage_panel.h).
  LinkagePanel& linkage_panel() { return linkage_panel_; }
  /// Carving and the swept envelope (shaping_panel.h).
  ShapingPanel& shaping() { return shaping_; }
  /// The panels held apart (their headers say what each owns).
  TimelinePanel& timeline();
  StatusBar& status_bar();
  StateGraphPanel& state_graph();
  AuthoringMenus& authoring();
  CollisionSettingsWindow& collision_settings();
  InspectorPanel& inspector();
  ViewportPanel& viewport();
  /// Hints and automatic resolution (the actions above forward there).
  ResolvePanel& resolve();

  // ---- what the UI shows (for tests and scripts) ----------------------------------------
  int active_transition() const { return active_transition_; }
  const std::vector<int>& open_transitions() const { return open_transitions_; }
  double time() const { return time_; }
  bool playing() const { return playing_; }
  int selected_part() const { return selected_part_; }
  std::optional<KeyRef> selected_key() const { return selected_key_; }
  const std::string& status() const { return status_; }
  bool status_is_error() const { return status_is_error_; }
  /// Whether the window with the whole status text is open (a status too long for the bar).
  bool status_window_open() const;
  const Layout& layout() const { return layout_; }
  view::Camera& camera() { return camera_; }
  const view::Camera& camera() const { return camera_; }
  /// How far a drag of one pixel turns the view (radians): 30° per 100 px, as Blender's orbit,
  /// slow enough for fine work.
  static constexpr double kOrbitPerPixel = 0.3 * std::numbers::pi / 180;
  /// The collision picture the UI shows this frame (null before a document is open).
  std::shared_ptr<const collision::CollisionSnapshot> collisions() const;
  /// The status bar's collision line: "collisions: 2 intervals in 1 transition, up to date",
  /// or how far detection is; empty before a document is open.
  std::string collision_summary() const;
  /// The selected part's pose at the current time.
  std::optional<motion::Pose> selected_pose() const;
  /// The selected part's keyframed track in the open transition, or null.
  const scene::KeyframedTrack* selected_keyframed_track() const;
  /// The gizmo as drawn this frame (for the selected part), if any.
  std::optional<Gizmo> gizmo() const;
  /// Screen position of time t on the scrub strip.
  ImVec2 timeline_point(double t) const;
  /// Screen position of the badge of transition `transition` in the state graph.
  std::optional<ImVec2> graph_edge_point(int transition) const;
  /// Screen position where a point of the world appears in the viewport image.
  std::optional<ImVec2> viewport_point(const Eigen::Vector3d& world) const;
  /// Ghosts of moving parts around the current time.
  bool show_ghosts = false;
  int ghost_count = 3;
  float ghost_spacing = 0.08f;
  bool show_intervals = true;

 private:
  friend class LinkagePanel;  // its edits and messages go through execute and the status line
  friend class TimelinePanel;  // the time, the selected key and the rows' layout
  friend class StateGraphPanel;  // the state shown and the graph's layout
  friend class AuthoringMenus;   // the state shown
  friend class InspectorPanel;   // playback, and the sculpt section (sculpt_panel.cpp)
  friend class ViewportPanel;    // the camera, renderer and the viewport's layout
  friend class ResolvePanel;     // its messages in the status line
  // Panels.
  void draw_menu_bar();
  void draw_modals();
  /// What the view refers to, by name, so a structural edit (or its undo) keeps showing the
  /// same transition, state and part, or something valid (authoring.cpp).
  struct ViewNames {
    std::vector<std::string> open_transitions;
    std::string active_transition, state, part;
    std::vector<int> open_indices;
    int active_index = -1, state_index = 0, part_index = -1;
    std::array<std::size_t, 3> counts{};  ///< parts, states, transitions
  };
  ViewNames remember_view() const;
  void restore_view(const ViewNames& names);
  void handle_shortcuts();

  void reset_view_for_new_document();
  /// What "frame all" frames: the active transition's whole motion, else the active state.
  Eigen::AlignedBox3d shown_bounds() const;
  bool step_history(bool forward);
  void advance_playback(double seconds);
  void set_status(std::string message, bool error = false);

  StudioOptions options_;
  std::unique_ptr<Document> document_;
  render::Renderer renderer_;
  view::Camera camera_;
  bool frame_pending_ = true;
  std::optional<CameraGlide> camera_glide_;  ///< a flight to a best view in progress
  std::unique_ptr<render::OcclusionCounter> occlusion_counter_;  ///< made at the first best view
  PipPanel pip_;
  LinkagePanel linkage_panel_;
  ShapingPanel shaping_;
  SculptPanel sculpt_;

  std::vector<int> open_transitions_;
  int active_transition_ = -1;
  int active_state_ = 0;  ///< shown when no transition is open
  double time_ = 0;
  bool playing_ = false;
  int selected_part_ = -1;
  std::optional<KeyRef> selected_key_;

  std::optional<std::chrono::steady_clock::time_point> last_frame_;
  std::chrono::steady_clock::time_point now_{};
  double seconds_ = 0;
  Layout layout_;
  std::string status_;
  bool status_is_error_ = false;
  std::filesystem::path recovery_candidate_;
  std::string open_path_input_, save_path_input_;
  bool show_open_dialog_ = false, show_save_as_dialog_ = false, confirm_close_ = false;
  bool quit_ = false;
  struct Panels;
  std::unique_ptr<Panels> panels_;
};

}  // namespace reconfig::studio
