#include "collision/detail/interval_ends.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>

#include "collision/detail/interval_merging.h"
#include "collision/detail/moving_bounds.h"
#include "collision/detail/spacetime_traversal.h"
#include "reconfig/collision/consolidate.h"
#include "reconfig/collision/contact_tolerance.h"

namespace reconfig::collision::detail {
namespace {

/// More re-detections than this per end and the end stays as found (a safeguard: each one
/// narrows the window 32 times or moves past it).
constexpr int kMaxRedetections = 64;

/// Re-detects one pair of parts over time windows, keeping the contacts that may belong to
/// one interval (their boxes meet its box).
class EndSearch {
 public:
  EndSearch(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PartProxy>& proxies,
            const DetectorOptions& options, const CollisionInterval& interval, DetectionStats& stats)
      : scene_(scene), trees_(trees), proxies_(proxies), options_(options), interval_(interval), stats_(stats) {
    options_.all_contacts = false;  // the same groups, sooner
    options_.contact = contact_tolerance(scene, options.contact);  // once, not per window
    pad_ = traversal_pad(scene, proxies);
  }

  /// The earliest start (`latest`: the latest end) of a contact of the interval in [lo, hi],
  /// refined to `kEndTolerance`; nothing if there is none.
  std::optional<double> earliest(double lo, double hi) { return extreme(lo, hi, false); }
  std::optional<double> latest(double lo, double hi) { return extreme(lo, hi, true); }

 private:
  std::vector<TriangleContact> detect(double lo, double hi) {
    std::vector<TriangleContact> found, kept;
    ++stats_.end_refinements;
    ++budget_;
    DetectionStats ignored;
    traverse_ranges(scene_, trees_, proxies_, options_, {{interval_.parts[0], interval_.parts[1], lo, hi}}, {}, found,
                    ignored, {}, pad_);
    for (const TriangleContact& c : found)
      if (!c.possible && boxes_meet(c.box, interval_.box)) kept.push_back(c);
    return kept;
  }

  /// The window's first start (last end) of a contact, re-detected in ever shorter windows
  /// that hold the contact piece it starts (ends): each 1/32 of the last, as a piece spans at
  /// most 1/32 of a step and the steps lie within the window. Only the first start (last end)
  /// is used, which the groups fix whatever contacts stand for them. When a short window turns
  /// out free, the search goes on past it.
  std::optional<double> extreme(double lo, double hi, bool last) {
    while (lo < hi && budget_ < kMaxRedetections) {
      const std::vector<TriangleContact> found = detect(lo, hi);
      if (found.empty()) return std::nullopt;
      double end = last ? found.front().t1 : found.front().t0;
      for (const TriangleContact& c : found) end = last ? std::max(end, c.t1) : std::min(end, c.t0);
      const double width = (hi - lo) / kNarrowPieces;
      if (width <= kEndTolerance || budget_ >= kMaxRedetections) return end;
      const double from = last ? std::max(lo, end - width) : end, to = last ? end : std::min(hi, end + width);
      if (const auto inside = extreme(from, to, last)) return inside;
      // Nothing in the short window: nothing before it either (after it, for the last end).
      if (last) hi = from;
      else lo = to;
    }
    return budget_ >= kMaxRedetections ? std::optional<double>(last ? hi : lo) : std::nullopt;
  }

  const scene::Reconfigurable& scene_;
  const BodyTrees& trees_;
  const std::vector<PartProxy>& proxies_;
  DetectorOptions options_;
  const CollisionInterval& interval_;
  DetectionStats& stats_;
  double pad_ = 0;
  int budget_ = 0;
};

/// The groups an interval consolidates: of its pair, within its time and box.
std::vector<const CollisionInterval*> groups_of(const std::vector<CollisionInterval>& groups,
                                                const CollisionInterval& interval) {
  std::vector<const CollisionInterval*> mine;
  for (const CollisionInterval& g : groups)
    if (!g.possible && g.parts == interval.parts && g.t0 >= interval.t0 && g.t1 <= interval.t1 &&
        interval.box.contains(g.box))
      mine.push_back(&g);
  return mine;
}

/// The refined start of an interval (`last`: end), or nothing if it holds no interference.
/// The windows searched are its groups' spans in order, from the first (the true start most
/// likely lies in it); each window is re-detected whole, so the result depends on the groups
/// alone, not on which contacts stand for them.
std::optional<double> refined_end(EndSearch& search, const std::vector<const CollisionInterval*>& mine,
                                  const CollisionInterval& interval, bool last) {
  std::vector<double> bounds;  // where the windows end (start, for the last end)
  for (const CollisionInterval* g : mine) bounds.push_back(last ? g->t0 : g->t1);
  std::sort(bounds.begin(), bounds.end());
  if (last) std::reverse(bounds.begin(), bounds.end());
  bounds.push_back(last ? interval.t0 : interval.t1);
  double from = last ? interval.t1 : interval.t0;
  for (const double bound : bounds) {
    if (last ? bound >= from : bound <= from) continue;
    if (const auto end = last ? search.latest(bound, from) : search.earliest(from, bound)) return end;
    from = bound;
  }
  return std::nullopt;
}

/// One end of one interval to refine, and what its refinement found.
struct EndTask {
  std::size_t interval = 0;
  bool last = false;  ///< the end (else the start)
  std::optional<double> refined;
  DetectionStats stats;
};

}  // namespace

void refine_interval_ends(const scene::Reconfigurable& scene, const BodyTrees& trees,
                          const std::vector<PartProxy>& proxies, const DetectorOptions& options,
                          std::vector<CollisionInterval>& groups, DetectionStats& stats) {
  if (options.conservative) return;  // its ends cover the true motion's: the proxies' would not
  std::vector<CollisionInterval> definite;
  for (const CollisionInterval& g : groups)
    if (!g.possible) definite.push_back(g);
  const std::vector<CollisionInterval> intervals = consolidate(definite, {});
  // Every end that can move (a start after 0, an end before 1, of an interval that has groups
  // of its own) is re-detected on its own, all of them in parallel: each depends on the
  // groups alone.
  std::vector<std::vector<const CollisionInterval*>> mine(intervals.size());
  std::vector<EndTask> tasks;
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    mine[i] = groups_of(groups, intervals[i]);
    if (mine[i].empty() || intervals[i].t0 == intervals[i].t1) continue;
    if (intervals[i].t0 > 0) tasks.push_back({i, false, {}, {}});
    if (intervals[i].t1 < 1) tasks.push_back({i, true, {}, {}});
  }
  tbb::parallel_for(std::size_t{0}, tasks.size(), [&](std::size_t k) {
    EndTask& task = tasks[k];
    EndSearch search(scene, trees, proxies, options, intervals[task.interval], task.stats);
    task.refined = refined_end(search, mine[task.interval], intervals[task.interval], task.last);
  });
  // The refined [t0, t1] of each interval (t0 > t1: no interference at all).
  std::vector<std::pair<double, double>> ends;
  for (const CollisionInterval& interval : intervals) ends.push_back({interval.t0, interval.t1});
  std::vector<bool> free(intervals.size(), false);  // a start with no interference after it
  for (const EndTask& task : tasks) {
    if (task.last && free[task.interval]) continue;  // as if never searched: nothing to refine
    stats += task.stats;
    if (!task.refined) {
      ends[task.interval] = {1, 0};
      free[task.interval] = !task.last;
    } else if (task.last) {
      ends[task.interval].second = *task.refined;
    } else {
      ends[task.interval].first = *task.refined;
    }
  }
  for (CollisionInterval& g : groups) {
    if (g.possible) continue;
    for (std::size_t i = 0; i < intervals.size(); ++i) {
      const CollisionInterval& interval = intervals[i];
      if (interval.parts != g.parts || g.t0 < interval.t0 || g.t1 > interval.t1 || !interval.box.contains(g.box))
        continue;
      g.t0 = std::max(g.t0, ends[i].first);
      g.t1 = std::min(g.t1, ends[i].second);
      break;
    }
  }
  std::erase_if(groups, [](const CollisionInterval& g) { return g.t0 > g.t1; });
}

}  // namespace reconfig::collision::detail
