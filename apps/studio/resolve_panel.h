#pragma once
/// @file
/// Resolving collisions in the studio: the hint (H) for the selected part — yellow arrows at its
/// keys in the viewport and on the timeline, a slider in the inspector that moves the steepest
/// element along its hint with live collision updates — and automatic resolution of the open
/// transition in the background, as one undoable edit. Its own state (the hint on screen, the
/// shapes it was computed from, the background hint and resolution), drawn by `draw` (the
/// inspector's section, like pip_panel.h). The studio's actions of the same names forward here.

#include <imgui.h>

#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "hint_view.h"
#include "reconfig/geometry/mesh.h"
#include "reconfig/render/draw_list.h"
#include "reconfig/resolve/auto_resolve.h"

namespace reconfig::studio {

class Studio;

class ResolvePanel {
 public:
  /// See Studio::request_hint, slide_along_hint, start_auto_resolve, cancel_auto_resolve.
  bool request_hint(Studio& studio);
  bool slide_along_hint(Studio& studio, double amount, bool live);
  bool start_auto_resolve(Studio& studio, bool move_times, bool move_states);
  void cancel_auto_resolve(Studio& studio);
  bool auto_resolving() const { return auto_resolve_ != nullptr; }
  bool hint_pending() const { return hint_job_ != nullptr; }
  const std::optional<HintView>& hint() const { return hint_; }
  /// Forgets the hint (a background one is waited for: it reads the design's shapes).
  void forget_hint();
  /// A new design: forgets the hint and cancels a running resolution.
  void reset();

  /// Each frame: takes a finished automatic resolution, and a hint computed in the background.
  void update(Studio& studio);
  /// The inspector's section: Hint and Resolve buttons, progress, the slider along the hint.
  void draw(Studio& studio);
  /// The hint's arrows (at translation keys and handles) and arcs (about the pivot, for
  /// rotation keys), for the viewport's draw list.
  void add_hint_arrows(const Studio& studio, render::DrawList& list) const;
  /// The hint's left/right arrows at the keys whose time it would move, on the timeline rows.
  void draw_timeline_hints(ImDrawList* draw, const Studio& studio) const;

 private:
  /// A hint is drawn only for the design version it was computed for (or slid to).
  bool hint_is_current(const Studio& studio) const;
  void poll_auto_resolve(Studio& studio);
  void poll_hint(Studio& studio);
  /// Shows a computed hint: the status line and the arrows.
  void show_hint(Studio& studio, HintView view);
  void draw_auto_resolve(Studio& studio);
  void draw_slider(Studio& studio);

  struct AutoResolveJob {
    ~AutoResolveJob() { cancel = true; }  // before the future waits for the thread to end
    int transition = -1;
    std::uint64_t version = 0;  ///< of the design it resolves: a result for another is dropped
    std::atomic<double> progress{0};
    std::atomic<bool> cancel{false};
    std::atomic<int> rounds{0};
    std::atomic<double> energy{0};  ///< the last round's pair's energy after it (shown as it falls)
    std::future<resolve::AutoResolveResult> result;
  };
  std::optional<HintView> hint_;
  resolve::ShapeCache hint_shapes_;
  std::vector<std::shared_ptr<const geometry::Mesh>> hint_shape_meshes_;  ///< what hint_shapes_ was built from
  std::unique_ptr<std::future<HintView>> hint_job_;  ///< a hint computed in the background (reads hint_shapes_)
  std::unique_ptr<AutoResolveJob> auto_resolve_;
  bool auto_resolve_moves_states_ = false;  ///< the inspector's "states may move"
};

}  // namespace reconfig::studio
