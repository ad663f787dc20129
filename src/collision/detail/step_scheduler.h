#pragma once
/// @file
/// The step scheduler: the search of every pair timeline, first breadth first level by level
/// (coarse time extents, a preview per level) while the levels are small, then depth first one
/// proxy step at a time, the steps in parallel — the even steps of each timeline first, each
/// odd step after its even neighbors, starting from the leaf pairs that made their extents —
/// best first within a step, with progress, previews and cancellation.

#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_for_each.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <utility>
#include <vector>

#include "collision/detail/bound_cache.h"
#include "collision/detail/contact_hints.h"
#include "collision/detail/urgency_queue.h"
#include "collision/detail/work_item.h"
#include "collision/detail/work_item_expansion.h"

namespace reconfig::collision::detail {

/// Work items per task in the breadth-first phase.
inline constexpr std::size_t kBreadthFirstGrain = 4;

/// Steps done between two progress reports (and previews) in the depth-first phase.
inline constexpr std::size_t kStepsPerReport = 16;

/// The groups of the contacts found so far, per pair timeline and proxy step: what pruning
/// relies on.
template <DopFamily family>
class FoundSteps {
 public:
  explicit FoundSteps(const TraversalInputs<family>& inputs) : inputs_(inputs), groups_(inputs.lines.size()) {
    for (std::size_t i = 0; i < inputs.lines.size(); ++i) groups_[i].resize(inputs.lines[i].times.size() - 1);
  }

  /// The groups of a step, or null while it has none.
  const StepGroups* of(int line, int step) const {
    const StepGroups& groups = groups_[line][step];
    return groups.empty() ? nullptr : &groups;
  }

  /// Adds a contact found on a pair timeline to the groups of its step (contacts over several
  /// steps, of parts holding still, prune nothing and are left out). Steps are independent:
  /// contacts of different steps may be added concurrently.
  void add(int line, const TriangleContact& contact) {
    const std::vector<double>& times = inputs_.lines[line].times;
    const int step = static_cast<int>(std::lower_bound(times.begin(), times.end(), contact.step_t0) - times.begin());
    if (step + 1 >= static_cast<int>(times.size()) || times[step + 1] != contact.step_t1) return;
    const auto [first, last] = inputs_.grid.frames_overlapping(times[step], times[step + 1]);
    StepGroups& groups = groups_[line][step];
    if (groups.empty()) groups.assign(last - first + 1, FrameContacts(inputs_.gap(line), false));
    const int frame = frame_of_contact(inputs_.grid, contact);
    assert(frame >= first && frame <= last);  // a step reports contacts in its own frames only
    groups[frame - first].add(contact);
  }

 private:
  const TraversalInputs<family>& inputs_;
  std::vector<std::vector<StepGroups>> groups_;
};

/// The search of every pair timeline of the inputs, from their roots over all their steps.
template <DopFamily family>
class TimelineSearch {
 public:
  /// @param contacts, stats  what the search finds is added here
  TimelineSearch(const TraversalInputs<family>& inputs, const std::vector<ContactHint>& hints,
                 std::vector<TriangleContact>& contacts, DetectionStats& stats, const DetectCallbacks& callbacks)
      : inputs_(inputs), found_(inputs), hinted_(hinted_leaves(inputs, hints)), contacts_(contacts), stats_(stats),
        callbacks_(callbacks) {}

  /// Finds the contacts, sorted by `contact_less`.
  /// @return false if cancelled through the callbacks' progress
  bool find_contacts() {
    std::vector<WorkItem> level;
    int max_depth = 1, max_steps = 1;
    for (int i = 0; i < static_cast<int>(inputs_.lines.size()); ++i) {
      const int steps = static_cast<int>(inputs_.lines[i].times.size()) - 1;
      level.push_back({i, BodyTree::kRoot, BodyTree::kRoot, 0, steps});
      max_depth = std::max(max_depth, inputs_.tree(i, 0).depth() + inputs_.tree(i, 1).depth());
      max_steps = std::max(max_steps, steps);
    }
    expected_levels_ = max_depth + std::ceil(std::log2(max_steps)) + 1;
    if (!search_breadth_first(level)) return false;
    if (!level.empty() && !search_steps_depth_first(level)) return false;
    std::sort(contacts_.begin(), contacts_.end(), contact_less);
    // A hinted leaf pair that the search reaches again reports the same contacts again.
    contacts_.erase(std::unique(contacts_.begin(), contacts_.end(),
                                [](const TriangleContact& x, const TriangleContact& y) {
                                  return !contact_less(x, y) && !contact_less(y, x) && x.possible == y.possible &&
                                         x.step_t0 == y.step_t0 && x.box.min() == y.box.min() && x.box.max() == y.box.max();
                                }),
                    contacts_.end());
    return true;
  }

 private:
  /// The groups found so far in a step (what an item's context reads).
  std::function<const StepGroups*(int, int)> step_groups() const {
    return [this](int line, int step) { return found_.of(line, step); };
  }

  /// The time ranges of the contacts found so far (for previews).
  std::vector<std::pair<double, double>> contact_ranges() const {
    std::vector<std::pair<double, double>> ranges;
    for (const TriangleContact& c : contacts_) ranges.push_back({c.t0, c.t1});
    return ranges;
  }

  /// Breadth first: coarse time extents level by level, while a level holds fewer items than
  /// the options' `breadth_first_items`; `level` is left holding the next level's items.
  /// @return false if cancelled
  bool search_breadth_first(std::vector<WorkItem>& level) {
    while (!level.empty() && level.size() < inputs_.options.breadth_first_items) {
      ++depth_;
      tbb::combinable<std::vector<WorkItem>> next_parts;
      tbb::combinable<std::vector<LineContact>> found_parts;
      tbb::combinable<DetectionStats> stat_parts;
      const auto expand_items = [&](std::size_t begin, std::size_t end) {
        auto& next = next_parts.local();
        const ItemContext context{step_groups(), found_parts.local(), stat_parts.local()};
        const BoundLookup<family> bounds{thread_bound_cache<family>(), search_id_};
        for (std::size_t i = begin; i < end; ++i) expand_work_item(inputs_, level[i], next, context, bounds);
      };
      // Items of these first levels span many steps (a bound over every sample of their range
      // each): worth a task of a few.
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size(), kBreadthFirstGrain),
                        [&](const tbb::blocked_range<std::size_t>& r) { expand_items(r.begin(), r.end()); });
      std::vector<WorkItem> next;
      next_parts.combine_each([&](const std::vector<WorkItem>& part) { next.insert(next.end(), part.begin(), part.end()); });
      std::vector<LineContact> batch;
      found_parts.combine_each([&](const std::vector<LineContact>& part) { batch.insert(batch.end(), part.begin(), part.end()); });
      // In an order that does not depend on the threads.
      std::sort(batch.begin(), batch.end(), [](const LineContact& x, const LineContact& y) {
        return contact_less(x.contact, y.contact) || (!contact_less(y.contact, x.contact) && x.line < y.line);
      });
      for (const LineContact& c : batch) {
        found_.add(c.line, c.contact);
        contacts_.push_back(c.contact);
      }
      stat_parts.combine_each([&](const DetectionStats& s) { stats_ += s; });
      stats_.levels = depth_;
      if (callbacks_.preview) {
        std::vector<std::pair<double, double>> ranges = contact_ranges();
        for (const WorkItem& item : next)
          ranges.push_back({inputs_.lines[item.pair].times[item.s0], inputs_.lines[item.pair].times[item.s1]});
        callbacks_.preview({depth_, union_of(std::move(ranges))});
      }
      if (!report_progress(callbacks_.progress, std::min(0.5, 0.5 * depth_ / expected_levels_))) return false;
      std::sort(next.begin(), next.end(), [](const WorkItem& x, const WorkItem& y) {
        return std::tie(x.pair, x.s0, x.node_a, x.node_b, x.s1) < std::tie(y.pair, y.s0, y.node_a, y.node_b, y.s1);
      });
      level = std::move(next);
    }
    return true;
  }

  /// The work items of one proxy step of one pair timeline: items_[begin, end).
  struct Step {
    std::size_t begin = 0, end = 0;
  };

  /// Cuts the items left after the breadth-first levels into single steps, grouped by step.
  void split_into_steps(const std::vector<WorkItem>& level) {
    for (const WorkItem& item : level)
      for (int s = item.s0; s < item.s1; ++s) items_.push_back({item.pair, item.node_a, item.node_b, s, s + 1});
    std::sort(items_.begin(), items_.end(), [](const WorkItem& x, const WorkItem& y) {
      return std::tie(x.pair, x.s0, x.node_a, x.node_b) < std::tie(y.pair, y.s0, y.node_a, y.node_b);
    });
    for (std::size_t i = 0; i < items_.size(); ++i)
      if (i == 0 || items_[i].pair != items_[i - 1].pair || items_[i].s0 != items_[i - 1].s0) steps_.push_back({i, i + 1});
      else steps_.back().end = i + 1;
  }

  /// The pair timeline and step index of step g.
  std::pair<int, int> timeline_step(std::size_t g) const { return {items_[steps_[g].begin].pair, items_[steps_[g].begin].s0}; }

  /// The even steps of every pair timeline first; an odd step waits for its even neighbors,
  /// then starts from the triangle pairs that made their extents in the frames they share
  /// (`neighbor_leaves`). Fills `even_neighbors_` and `odd_neighbors_`.
  void link_odd_steps_to_even_neighbors() {
    std::map<std::pair<int, int>, std::size_t> index_of;
    for (std::size_t g = 0; g < steps_.size(); ++g) index_of.emplace(timeline_step(g), g);
    even_neighbors_.assign(steps_.size(), {});
    odd_neighbors_.assign(steps_.size(), {});
    for (std::size_t g = 0; g < steps_.size(); ++g) {
      const auto [pair, s] = timeline_step(g);
      if (s % 2 == 0) continue;
      for (const int next : {s - 1, s + 1})
        if (const auto at = index_of.find({pair, next}); at != index_of.end()) {
          even_neighbors_[g].push_back(at->second);
          odd_neighbors_[at->second].push_back(g);
        }
    }
  }

  /// Marks step g done and, every `kStepsPerReport` steps, reports progress and a preview, one
  /// call at a time; a progress callback that returns false cancels the search.
  void report_step_done(std::size_t g) {
    const std::lock_guard lock(reporting_);
    if (cancelled_) return;
    finished_[g] = true;
    for (const LineContact& c : step_contacts_[g]) found_ranges_.push_back({c.contact.t0, c.contact.t1});
    if (++done_ % kStepsPerReport != 0 && done_ != steps_.size()) return;
    if (callbacks_.preview) {
      std::vector<std::pair<double, double>> ranges = found_ranges_;
      for (std::size_t h = 0; h < steps_.size(); ++h)
        if (!finished_[h]) {
          const auto [pair, s] = timeline_step(h);
          ranges.push_back({inputs_.lines[pair].times[s], inputs_.lines[pair].times[s + 1]});
        }
      callbacks_.preview({depth_, union_of(std::move(ranges))});
    }
    if (!report_progress(callbacks_.progress, 0.5 + 0.5 * static_cast<double>(done_) / steps_.size())) cancelled_ = true;
  }

  /// Searches step g best first: the item whose reach sticks out of the groups found so far
  /// the most for its size (children inherit their parent's protrusion), so that the contacts
  /// that make the groups' extremes come early and prune the rest; first of all the hinted
  /// leaf pairs, then the items where nothing is known yet, deepest first (to find a first
  /// contact soon). The contacts found join the step's groups at once.
  void search_step(std::size_t g, UrgencyQueue<WorkItem>& queue) {
    std::vector<LineContact>& local = step_contacts_[g];
    const ItemContext context{step_groups(), local, step_stats_[g]};
    const BoundLookup<family> bounds{thread_bound_cache<family>(), search_id_};
    std::vector<WorkItem> children;
    const auto expand = [&](const WorkItem& item) {
      const std::size_t known = local.size();
      const double urgency = expand_work_item(inputs_, item, children, context, bounds);
      for (std::size_t c = known; c < local.size(); ++c) found_.add(local[c].line, local[c].contact);
      return urgency;
    };
    const auto [pair, s] = timeline_step(g);
    std::vector<std::pair<int, int>> leaves;
    if (const auto at = hinted_.find({pair, s}); at != hinted_.end()) leaves = at->second;
    for (const std::size_t h : even_neighbors_[g])
      for (const auto& leaf_pair : neighbor_leaves(inputs_, pair, s, step_contacts_[h])) leaves.push_back(leaf_pair);
    sort_unique(leaves);
    for (const auto& [leaf_a, leaf_b] : leaves) expand({pair, leaf_a, leaf_b, s, s + 1});
    for (std::size_t i = steps_[g].end; i-- > steps_[g].begin;) queue.push(items_[i], kUnknownUrgency);
    while (!queue.empty()) {
      const double urgency = expand(queue.pop());
      for (auto child = children.rbegin(); child != children.rend(); ++child) queue.push(*child, urgency);
      children.clear();
    }
  }

  /// Depth first, one step of one pair timeline at a time (the steps in parallel): contacts
  /// found grow the groups of the step's frames at once, and what they cover is skipped. A
  /// step starts as soon as a thread is free and its even neighbors are done: there is no
  /// barrier between the rounds, and what a step finds depends on nothing else.
  /// @return false if cancelled
  bool search_steps_depth_first(const std::vector<WorkItem>& level) {
    split_into_steps(level);
    link_odd_steps_to_even_neighbors();
    const auto waiting = std::make_unique<std::atomic<int>[]>(steps_.size());
    std::vector<std::size_t> ready;  // the even steps, and the odd ones without even neighbors
    for (std::size_t g = 0; g < steps_.size(); ++g) {
      waiting[g] = static_cast<int>(even_neighbors_[g].size());
      if (even_neighbors_[g].empty()) ready.push_back(g);
    }
    step_contacts_.assign(steps_.size(), {});
    step_stats_.assign(steps_.size(), {});
    finished_.assign(steps_.size(), false);
    found_ranges_ = contact_ranges();
    tbb::enumerable_thread_specific<UrgencyQueue<WorkItem>> queues;  // empty between steps, their memory kept
    tbb::parallel_for_each(ready.begin(), ready.end(), [&](std::size_t g, tbb::feeder<std::size_t>& feeder) {
      if (cancelled_) return;
      search_step(g, queues.local());
      for (const std::size_t odd : odd_neighbors_[g])
        if (--waiting[odd] == 0) feeder.add(odd);
      report_step_done(g);
    });
    if (cancelled_) return false;
    for (const bool odd : {false, true})
      for (std::size_t g = 0; g < steps_.size(); ++g)
        if ((timeline_step(g).second % 2 == 1) == odd) {
          for (const LineContact& c : step_contacts_[g]) contacts_.push_back(c.contact);
          stats_ += step_stats_[g];
        }
    return true;
  }

  const TraversalInputs<family>& inputs_;
  FoundSteps<family> found_;
  StepLeaves hinted_;
  std::vector<TriangleContact>& contacts_;
  DetectionStats& stats_;
  const DetectCallbacks& callbacks_;
  const std::uint64_t search_id_ = new_search_id();  ///< its bounds in the threads' caches
  double expected_levels_ = 1;  ///< for progress: tree depths plus the halvings of the steps
  int depth_ = 0;               ///< breadth-first levels done

  // The depth-first phase.
  std::vector<WorkItem> items_;  ///< single-step items, grouped by step
  std::vector<Step> steps_;
  std::vector<std::vector<std::size_t>> even_neighbors_;  ///< of an odd step
  std::vector<std::vector<std::size_t>> odd_neighbors_;   ///< of an even step: those it unblocks
  std::vector<std::vector<LineContact>> step_contacts_;
  std::vector<DetectionStats> step_stats_;
  std::mutex reporting_;
  std::size_t done_ = 0;
  std::vector<bool> finished_;
  std::vector<std::pair<double, double>> found_ranges_;
  std::atomic<bool> cancelled_ = false;
};

}  // namespace reconfig::collision::detail
