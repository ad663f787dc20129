#pragma once
/// @file
/// The timeline of the open transitions: tabs, the scrub strip, collision bands (faint previews
/// while detection is coarse, then solid), and the selected part's keys (translation and
/// rotation rows) that can be selected, dragged in time, inserted and removed. Its own state
/// (the scrub and a key's drag), drawn by `draw` (like pip_panel.h); the time, the selected key
/// and the rows' places (Studio::layout) are the studio's.

#include <imgui.h>

#include <optional>
#include <vector>

#include "reconfig/scene/reconfigurable.h"
#include "studio.h"

namespace reconfig::collision {
struct TransitionSnapshot;
}

namespace reconfig::studio {

class TimelinePanel {
 public:
  void draw(Studio& studio);
  /// The time strip or a key is being dragged (the viewport draws coarser meanwhile).
  bool dragging() const { return scrubbing_ || key_drag_.has_value(); }
  /// Drops a key's drag (a new design was opened).
  void cancel_drag() { key_drag_.reset(); }

 private:
  /// Where the rows are this frame: times map to x in [x0, x1]; labels start at label_x.
  struct Strip {
    float label_x = 0, label_width = 0, x0 = 0, x1 = 0;
    float scrub_y = 0, bands_y = 0, translation_y = 0, rotation_y = 0;  ///< rows' tops
    float width() const { return x1 - x0; }
    float x_of(double time) const { return static_cast<float>(x0 + time * (x1 - x0)); }
    double t_of(float x) const;
  };
  /// One tab per open transition. @return whether one is active
  bool draw_tabs(Studio& studio);
  void draw_controls(Studio& studio);
  /// The rows under the cursor, their places recorded in the studio's layout.
  Strip place_rows(Studio& studio, const scene::Reconfigurable& scene);
  void draw_labels(const Studio& studio, ImDrawList* draw, const Strip& strip);
  void draw_scrub(Studio& studio, ImDrawList* draw, const Strip& strip);
  void draw_bands(Studio& studio, ImDrawList* draw, const Strip& strip);
  /// The hovered band's parts and times; P opens the picture-in-picture on it.
  void draw_band_tooltip(Studio& studio, const collision::TransitionSnapshot& current, const Strip& strip);
  void draw_keys(Studio& studio, ImDrawList* draw, const Strip& strip);
  /// The selected part's keyframed track in the active transition (null when it has none, or
  /// screw poses, drawn here as dots).
  const scene::KeyframedTrack* draw_track_kind(const Studio& studio, ImDrawList* draw, const Strip& strip);
  void draw_key_row(Studio& studio, ImDrawList* draw, const Strip& strip, scene::KeyKind kind,
                    const std::vector<double>& times);

  bool scrubbing_ = false;            ///< the time strip is being dragged
  std::optional<KeyRef> key_drag_;    ///< the key being dragged in time
  double key_drag_time_ = 0;          ///< where it is dragged to
};

}  // namespace reconfig::studio
