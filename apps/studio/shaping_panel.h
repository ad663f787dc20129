#pragma once
/// @file
/// Shaping parts by the motion of others in the studio (the sweep module): Collisions > Carve…
/// carves the selected part by the volume other parts sweep through it over the open
/// transition (reconfigurables §6.7: A ← A \ offset(sweep(B), ε)), in the background with
/// progress and cancel, as one undoable edit of its mesh; View > Swept envelope shows the screw
/// envelope (Rossignac & Kim) of the selected part over the open transition, translucent, and
/// follows every edit. While the Carve window is open, the volume its carvers sweep through the
/// part is previewed translucent on the part (carve_preview.h). Its own state, drawn by `draw`
/// (like pip_panel.h).

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reconfig/collision/collision_interval.h"
#include "reconfig/geometry/mesh.h"
#include "reconfig/render/draw_list.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/sweep/carve_part.h"
#include "carve_preview.h"

namespace reconfig::studio {

class Studio;

class ShapingPanel {
 public:
  /// What a carve cuts, and how finely.
  struct CarveSettings {
    std::vector<std::string> carvers;  ///< the parts whose sweeps are subtracted
    double offset = 0.005;             ///< ε, scene units
    double grid = 0;                   ///< grid step h; 0: 1/128 of the swept box
    /// The part of the open transition whose motion carves: all of it, or a collision interval.
    double from = 0, to = 1;
  };

  /// Starts carving the selected part by `settings.carvers` over [from, to] of the open
  /// transition, in the background; the result arrives (in `update`) as one undoable edit of
  /// the part's mesh.
  /// @return false (the status line says why) with no part or transition, no or unknown
  ///   carvers, the part among them, a time range outside [0, 1], or a carve already running
  bool start_carve(Studio& studio, const CarveSettings& settings);
  /// Stops a running carve; nothing is changed.
  void cancel_carve(Studio& studio);
  bool carving() const { return job_ != nullptr; }
  /// The running carve's progress in [0, 1] (0 when none).
  double carve_progress() const { return job_ ? job_->progress.load() : 0.0; }
  /// Opens the Carve window for the selected part (the carvers preset to the parts it collides
  /// with in the open transition, over all of it; its time range can be narrowed to one of the
  /// part's collision intervals, whose other part then carves).
  void show_carve_window(Studio& studio);
  /// The selected part's collision intervals in the open transition (the Carve window's time
  /// ranges besides the whole transition).
  std::vector<collision::CollisionInterval> part_intervals(const Studio& studio) const;
  /// Narrows the open Carve window to `interval`: its time range, carved by its other parts.
  void choose_interval(Studio& studio, const collision::CollisionInterval& interval);
  /// The Carve window's settings while it is open.
  const std::optional<CarveSettings>& carve_window() const { return carve_draft_; }
  /// Sets the open Carve window's carvers (checks), offset and grid, as if typed in.
  /// @return false (the status line says why) when the window is closed or a carver unknown
  bool set_carve_window(Studio& studio, const CarveSettings& settings);
  /// The open Carve window's preview: the carvers' swept volumes (offset, clipped to the part's
  /// box) in the carved part's rest frame, once computed for the window's current settings
  /// and the current design (null before, and when the window is closed).
  std::shared_ptr<const geometry::Mesh> carve_preview(const Studio& studio) const;
  bool carve_preview_computing() const { return preview_.computing(); }
  /// Changes whenever what this panel adds to the viewport does (the preview arrives or goes).
  std::uint64_t overlay_revision() const { return preview_.revision() + (envelope_shown_ ? 1ull << 63 : 0); }

  /// The translucent swept envelope of the selected part over the open transition.
  void set_envelope_shown(bool shown) { envelope_shown_ = shown; }
  bool envelope_shown() const { return envelope_shown_; }
  /// The envelope on screen, in world space (null when hidden or nothing is selected).
  std::shared_ptr<const geometry::Mesh> envelope(const Studio& studio);
  /// Adds the envelope (when shown) to the viewport's draw list.
  void add_to_draw_list(const Studio& studio, render::DrawList& list);

  /// Each frame: takes a finished carve. Then the Carve window and the progress window.
  void update(Studio& studio);
  void draw(Studio& studio);

 private:
  /// The Carve window's "over" choice: the whole transition or one of `part_intervals`.
  void draw_time_range(Studio& studio);
  struct CarveJob {
    ~CarveJob() { cancel = true; }  // before the future waits for the thread to end
    std::string part;
    std::uint64_t version = 0;  ///< of the design carved: a result for another is dropped
    std::atomic<double> progress{0};
    std::atomic<bool> cancel{false};
    std::future<sweep::CarveResult> result;
  };
  void finish_carve(Studio& studio, sweep::CarveResult result);
  /// The preview the open Carve window asks for (none when it is closed).
  std::optional<CarvePreview::Key> preview_key(const Studio& studio) const;
  void draw_preview_status(const Studio& studio);
  void add_preview_to_draw_list(const Studio& studio, render::DrawList& list) const;

  std::unique_ptr<CarveJob> job_;
  std::optional<CarveSettings> carve_draft_;  ///< the Carve window, while it is open
  std::vector<char> carver_checks_;           ///< per part, in the Carve window
  CarvePreview preview_;                      ///< of the Carve window's settings
  std::optional<CarvePreview::Key> preview_stopped_;  ///< cancelled by the user: not restarted

  bool envelope_shown_ = false;
  struct EnvelopeKey {
    const void* scene = nullptr;
    int transition = -1, part = -1;
    bool operator==(const EnvelopeKey&) const = default;
  };
  std::optional<EnvelopeKey> envelope_key_;
  std::shared_ptr<const geometry::Mesh> envelope_;
  std::shared_ptr<const scene::Reconfigurable> envelope_scene_;  ///< the design version it is of
};

}  // namespace reconfig::studio
