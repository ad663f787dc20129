#pragma once
/// @file
/// The picture-in-picture panel (reconfigurables §4.4, Fig. 10): after an edit, the most
/// critical side effect (side_effects.h) that is not the collision being worked on opens in a
/// small view of its own, view-optimized (§4.3), at its severity time, marked in yellow on the
/// timeline. It follows further edits; clicking it swaps it with the main view (time, camera,
/// selection); P over a band of the timeline opens it there by hand; it can be closed. Its own
/// state, drawn by `draw` (Dear ImGui's ExampleAppConsole style). The severity time and the
/// best view are searched on a thread of their own (view_search.h): meanwhile the picture
/// shows what it showed, or a spinner.

#include <imgui.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/render/render_target.h"
#include "reconfig/view/camera.h"
#include "view_search.h"

namespace reconfig::studio {

class Studio;

class PipPanel {
 public:
  /// What the picture shows.
  struct Target {
    int transition = -1;
    collision::CollisionInterval interval;
    double time = 0;  ///< the interval's severity time
    view::Camera camera;
  };

  /// Each frame: takes the view searched for, if it came; when a new up-to-date result of the
  /// active transition arrived after an edit, opens on its most critical side effect, or
  /// follows the one it shows (closing when it is gone). The interval being worked on is the
  /// one focused (side_effects.h) when the time or the selection last changed, followed
  /// through the edits since.
  void update(Studio& studio);
  /// The window over the viewport's top right corner, when open.
  void draw(Studio& studio);
  /// The yellow mark of the picture's time on the timeline's time strip.
  void draw_timeline_marker(ImDrawList* draw, const Studio& studio) const;

  /// Starts the search of `interval` of `transition` (its severity time and best view): the
  /// picture shows it when found.
  void open_on(Studio& studio, int transition, const collision::CollisionInterval& interval);
  /// Swaps the main view and the picture: time, camera and the interval focused on (a search
  /// under way is dropped).
  void swap(Studio& studio);
  void close();

  /// What the picture shows (the last search found).
  const std::optional<Target>& target() const { return target_; }
  /// A search is under way: `target` is not yet what it will show.
  bool searching() const { return pending_.has_value(); }
  /// Where the picture is on screen this frame (zero when closed).
  ImVec2 image_min() const { return image_min_; }
  ImVec2 image_max() const { return image_max_; }

  static constexpr int kWidth = 320, kHeight = 220;

 private:
  /// What is searched for: `target_` once found.
  struct Pending {
    std::uint64_t id = 0;  ///< of the search
    int transition = -1;
    collision::CollisionInterval interval;
  };
  void take_search_result();
  void draw_spinner(ImDrawList* draw, ImVec2 center, float radius) const;

  std::optional<Target> target_;
  std::optional<Pending> pending_;
  std::unique_ptr<ViewSearch> search_;  ///< made at the first search
  std::string error_;  ///< why the last search found no view (no OpenGL context for it)
  /// The collision being worked on: focused where the designer last set the time or selection
  /// (focus_time_, focus_part_), followed through edits.
  std::optional<collision::CollisionInterval> worked_on_;
  double focus_time_ = -1;
  int focus_part_ = -1;
  std::uint64_t seen_version_ = 0;
  render::RenderTarget image_;
  std::uint64_t drawn_version_ = 0;  ///< design version the image shows (0: must draw)
  ImVec2 image_min_{0, 0}, image_max_{0, 0};
};

}  // namespace reconfig::studio
