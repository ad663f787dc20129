#pragma once
/// @file
/// The inspector: the selected part's pose at the current time as numbers (editing them sets a
/// key or the state pose), the selected key with its Bézier handles, the resolve and sculpt
/// sections, undo/redo, ghost settings and the list of collision intervals of the open
/// transition. Drawn by `draw` (like pip_panel.h); it holds no state of its own: what it shows
/// and edits is the studio's (and the resolve section's, resolve_panel.h).

namespace reconfig::studio {

class Studio;

class InspectorPanel {
 public:
  void draw(Studio& studio);

 private:
  void draw_part(Studio& studio);
  void draw_selected_key(Studio& studio);
  void draw_history(Studio& studio);
  void draw_ghosts(Studio& studio);
  /// The collision intervals of the open transition; clicking one jumps to it.
  void draw_intervals(Studio& studio);
};

}  // namespace reconfig::studio
