#include "collision/detail/interval_ends.h"

#include <algorithm>
#include <optional>

#include "collision/detail/interval_merging.h"
#include "collision/detail/spacetime_traversal.h"
#include "reconfig/collision/consolidate.h"

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
      : scene_(scene), trees_(trees), proxies_(proxies), options_(options), interval_(interval), stats_(stats) {}

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
                    ignored, {});
    for (const TriangleContact& c : found)
      if (!c.possible && boxes_meet(c.box, interval_.box)) kept.push_back(c);
    return kept;
  }

  /// The window's first (or last) contact piece, re-detected inside it until it is short
  /// enough; when a piece turns out free, the search goes on past it.
  std::optional<double> extreme(double lo, double hi, bool last) {
    while (lo < hi && budget_ < kMaxRedetections) {
      const std::vector<TriangleContact> found = detect(lo, hi);
      if (found.empty()) return std::nullopt;
      const auto at = last ? std::max_element(found.begin(), found.end(),
                                              [](const auto& x, const auto& y) { return x.t1 < y.t1; })
                           : std::min_element(found.begin(), found.end(),
                                              [](const auto& x, const auto& y) { return x.t0 < y.t0; });
      const TriangleContact piece = *at;
      const bool narrowed = piece.t1 - piece.t0 < hi - lo;
      if (piece.t1 - piece.t0 <= kEndTolerance || !narrowed || budget_ >= kMaxRedetections)
        return last ? piece.t1 : piece.t0;
      if (const auto inside = extreme(piece.t0, piece.t1, last)) return inside;
      // Nothing in the piece: nothing before it either (or after it, for the last end).
      if (last) hi = piece.t0;
      else lo = piece.t1;
    }
    return budget_ >= kMaxRedetections ? std::optional<double>(last ? hi : lo) : std::nullopt;
  }

  const scene::Reconfigurable& scene_;
  const BodyTrees& trees_;
  const std::vector<PartProxy>& proxies_;
  const DetectorOptions& options_;
  const CollisionInterval& interval_;
  DetectionStats& stats_;
  int budget_ = 0;
};

/// The interval's known contacts: of its pair, within its time, their boxes meeting its box.
std::vector<const TriangleContact*> contacts_of(const std::vector<TriangleContact>& contacts,
                                                const CollisionInterval& interval) {
  std::vector<const TriangleContact*> mine;
  for (const TriangleContact& c : contacts)
    if (!c.possible && c.part_a == interval.parts[0] && c.part_b == interval.parts[1] && c.t0 >= interval.t0 &&
        c.t1 <= interval.t1 && boxes_meet(c.box, interval.box))
      mine.push_back(&c);
  return mine;
}

/// The refined start of an interval (`last`: end), or nothing if it holds no interference.
/// The windows searched are the known contacts' pieces in order, from the first (the true start
/// most likely lies in it); each window is re-detected whole, so contacts the traversal skipped
/// between the known ones are found too.
std::optional<double> refined_end(EndSearch& search, const std::vector<const TriangleContact*>& mine,
                                  const CollisionInterval& interval, bool last) {
  std::vector<double> bounds;  // where the windows end (start, for the last end)
  for (const TriangleContact* c : mine) bounds.push_back(last ? c->t0 : c->t1);
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

/// The refined [t0, t1] of one interval (t0 > t1: no interference at all).
std::pair<double, double> refined(const scene::Reconfigurable& scene, const BodyTrees& trees,
                                  const std::vector<PartProxy>& proxies, const DetectorOptions& options,
                                  const std::vector<TriangleContact>& contacts, const CollisionInterval& interval,
                                  DetectionStats& stats) {
  double t0 = interval.t0, t1 = interval.t1;
  const std::vector<const TriangleContact*> mine = contacts_of(contacts, interval);
  if (mine.empty() || t0 == t1) return {t0, t1};
  if (t0 > 0) {
    EndSearch search(scene, trees, proxies, options, interval, stats);
    const std::optional<double> start = refined_end(search, mine, interval, false);
    if (!start) return {1, 0};
    t0 = *start;
  }
  if (t1 < 1) {
    EndSearch search(scene, trees, proxies, options, interval, stats);
    const std::optional<double> end = refined_end(search, mine, interval, true);
    if (!end) return {1, 0};
    t1 = *end;
  }
  return {t0, t1};
}

}  // namespace

void refine_interval_ends(const scene::Reconfigurable& scene, const BodyTrees& trees,
                          const std::vector<PartProxy>& proxies, const DetectorOptions& options,
                          const std::vector<TriangleContact>& contacts, std::vector<CollisionInterval>& groups,
                          DetectionStats& stats) {
  std::vector<CollisionInterval> definite;
  for (const CollisionInterval& g : groups)
    if (!g.possible) definite.push_back(g);
  const std::vector<CollisionInterval> intervals = consolidate(definite, {});
  std::vector<std::pair<double, double>> ends;
  for (const CollisionInterval& interval : intervals)
    ends.push_back(refined(scene, trees, proxies, options, contacts, interval, stats));
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
