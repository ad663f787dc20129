#include "reconfig/collision/spacetime_detector.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "collision/detail/spacetime_traversal.h"
#include "reconfig/geometry/bounding_box.h"
#include "collision/detail/deep_inside.h"
#include "collision/detail/interval_ends.h"
#include "reconfig/collision/contact_tolerance.h"

namespace reconfig::collision {
namespace {

/// The box of a part's placed bounding box at time t of its proxy (the box of the placed
/// corners): it holds every placed vertex.
Eigen::AlignedBox3d placed_box(const BodyTrees& trees, const std::vector<PartProxy>& proxies, int part, double t) {
  const BodyTree::Node& root = trees[part]->node(BodyTree::kRoot);
  Eigen::MatrixX3d corners(8, 3);
  for (int c = 0; c < 8; ++c)
    for (int axis = 0; axis < 3; ++axis) corners(c, axis) = root.center[axis] + ((c >> axis) & 1 ? 1 : -1) * root.half[axis];
  return geometry::bounding_box(detail::proxy_points(proxies[part], corners, t));
}

/// Whether part `inner` lies inside part `outer` at time t of their proxies, their surfaces
/// not crossing then: one vertex of each of its components lies inside `outer`'s solid. The
/// whole outer mesh is posed only if those vertices lie within `outer_box`, its placed box.
bool nested(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PartProxy>& proxies, int inner,
            int outer, double t, const Eigen::AlignedBox3d& outer_box, double delta) {
  const std::vector<int>& probes = trees[inner]->component_vertices();
  Eigen::MatrixX3d rest(static_cast<Eigen::Index>(probes.size()), 3);
  for (std::size_t i = 0; i < probes.size(); ++i) rest.row(static_cast<Eigen::Index>(i)) = scene.parts[inner].mesh.V.row(probes[i]);
  const Eigen::MatrixX3d points = detail::proxy_points(proxies[inner], rest, t);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!outer_box.contains(points.row(i).transpose())) return false;
  const geometry::Mesh posed{detail::proxy_vertices(scene, proxies[outer], outer, t), scene.parts[outer].mesh.F};
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (const auto side = detail::deep_side(posed, points.row(i).transpose(), delta)) {
      if (!*side) return false;
    } else if (!detail::lies_inside(posed, detail::proxy_vertices(scene, proxies[inner], inner, t), 0, delta)) {
      return false;  // the probe touches the outer surface: another vertex decides
    }
  }
  return true;
}

}  // namespace

DetectionStats& DetectionStats::operator+=(const DetectionStats& other) {
  bound_tests += other.bound_tests;
  narrow_phase += other.narrow_phase;
  narrow_pieces += other.narrow_pieces;
  contact_tests += other.contact_tests;
  containment_tests += other.containment_tests;
  pruned += other.pruned;
  levels = std::max(levels, other.levels);
  proxy_samples += other.proxy_samples;
  end_refinements += other.end_refinements;
  return *this;
}

BodyTrees build_body_trees(const scene::Reconfigurable& scene) {
  BodyTrees trees;
  for (const scene::Part& part : scene.parts) trees.push_back(std::make_shared<const BodyTree>(part.mesh));
  return trees;
}

SpacetimeDetector::SpacetimeDetector(int transition, DetectorOptions options)
    : transition_(transition), options_(options) {
  if (options_.clearance > 0 && options_.closer_than == 0) {
    DetectorOptions closer = options_;
    closer.closer_than = options_.clearance;
    closer.clearance = 0;
    closer.detect_containment = false;  // nesting is interference, found by the collision traversal
    closer_ = std::make_unique<SpacetimeDetector>(transition, closer);
  }
}

namespace {

/// The callbacks of one of two passes: progress over [from, from + 0.5] when `halved`.
DetectCallbacks pass_callbacks(const DetectCallbacks& callbacks, bool halved, double from) {
  if (!halved) return callbacks;
  DetectCallbacks pass;
  if (callbacks.progress) pass.progress = [&callbacks, from](double f) { return callbacks.progress(from + 0.5 * f); };
  if (from == 0) pass.preview = callbacks.preview;  // the previews show where collisions may be found
  return pass;
}

/// The clearance intervals: the groups of the clearance traversal less the times the same
/// pair of parts collides (its groups and containments), flagged `clearance`.
std::vector<CollisionInterval> clearance_intervals(const std::vector<CollisionInterval>& near,
                                                   const std::vector<CollisionInterval>& groups,
                                                   const std::vector<Containment>& containments) {
  std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> colliding;
  for (const CollisionInterval& g : groups) colliding[{g.parts[0], g.parts[1]}].push_back({g.t0, g.t1});
  for (const Containment& c : containments)
    colliding[{std::min(c.inner, c.outer), std::max(c.inner, c.outer)}].push_back({c.t0, c.t1});
  for (auto& [pair, ranges] : colliding) ranges = detail::union_of(std::move(ranges));
  std::vector<CollisionInterval> clearances;
  for (const CollisionInterval& g : near) {
    CollisionInterval left = g;
    left.clearance = true;
    left.possible = false;
    const auto at = colliding.find({g.parts[0], g.parts[1]});
    if (at != colliding.end())
      for (const auto& [t0, t1] : at->second) {
        if (t1 < left.t0 || t0 > left.t1) continue;
        if (t0 > left.t0) {  // the part before the collision
          CollisionInterval before = left;
          before.t1 = t0;
          clearances.push_back(before);
        }
        left.t0 = t1;
        if (left.t0 >= left.t1) break;
      }
    if (left.t0 < left.t1 || (left.t0 == left.t1 && g.t0 == g.t1)) clearances.push_back(left);
  }
  std::sort(clearances.begin(), clearances.end(), [](const CollisionInterval& x, const CollisionInterval& y) {
    return std::tie(x.t0, x.parts, x.t1) < std::tie(y.t0, y.parts, y.t1);
  });
  return clearances;
}

}  // namespace

std::vector<CollisionInterval> SpacetimeDetector::intervals() const {
  std::vector<CollisionInterval> all = groups_;
  all.insert(all.end(), clearances_.begin(), clearances_.end());
  return all;
}

bool SpacetimeDetector::check_clearance(const scene::Reconfigurable& scene, const BodyTrees& trees,
                                        const ChangedRanges* changed, const DetectCallbacks& callbacks) {
  if (!closer_) return true;
  const DetectCallbacks pass = pass_callbacks(callbacks, true, 0.5);
  closer_->proxies_ = proxies_;  // the same motion: the proxies are not built twice
  if (!(changed ? closer_->retraverse_changed(scene, trees, *changed, pass) : closer_->traverse_all(scene, trees, pass))) {
    valid_ = false;
    return false;
  }
  clearances_ = clearance_intervals(closer_->groups(), groups_, containments_);
  DetectionStats near = closer_->last_stats();
  near.proxy_samples = 0;  // the same proxies
  stats_ += near;
  return true;
}

bool SpacetimeDetector::detect(const scene::Reconfigurable& scene, const BodyTrees& trees,
                               const DetectCallbacks& callbacks) {
  valid_ = false;
  const int n = static_cast<int>(scene.parts.size());
  proxies_.assign(n, {});
  tbb::parallel_for(0, n, [&](int p) {
    proxies_[p] = build_part_proxy(scene, transition_, p, options_.tolerance, options_.min_step);
  });
  if (!traverse_all(scene, trees, pass_callbacks(callbacks, closer_ != nullptr, 0))) return false;
  return check_clearance(scene, trees, nullptr, callbacks);
}

bool SpacetimeDetector::traverse_all(const scene::Reconfigurable& scene, const BodyTrees& trees,
                                     const DetectCallbacks& callbacks) {
  valid_ = false;
  stats_ = {};
  contacts_.clear();
  containments_.clear();
  std::vector<PairRange> work;  // the pairs that may meet: memory linear in them, not in n²
  for (const detail::TraversalRange& r : detail::candidate_pairs(trees, proxies_, scene, options_))
    work.push_back({r.a, r.b, r.t0, r.t1});
  if (!traverse(scene, trees, work, {}, callbacks)) return false;
  valid_ = true;
  return true;
}

bool SpacetimeDetector::update(const scene::Reconfigurable& scene, const BodyTrees& trees,
                               const scene::DirtySet& dirty, const DetectCallbacks& callbacks) {
  if (!valid_ || dirty.structure_changed || !dirty.geometry_changed.empty() ||
      proxies_.size() != scene.parts.size())
    return detect(scene, trees, callbacks);
  // Rebuild the proxies of the dirty parts (a proxy is a function of the motion alone, so the
  // result equals a detection from scratch) and find where they changed.
  std::set<int> dirty_parts;
  for (const scene::DirtyRange& range : dirty.ranges)
    if (range.transition == transition_) dirty_parts.insert(range.part);
  ChangedRanges changed;
  for (int part : dirty_parts) {
    PartProxy fresh = build_part_proxy(scene, transition_, part, options_.tolerance, options_.min_step);
    if (const auto range = changed_range(proxies_[part], fresh)) changed[part].push_back(*range);
    proxies_[part] = std::move(fresh);
  }
  if (!retraverse_changed(scene, trees, changed, pass_callbacks(callbacks, closer_ != nullptr, 0))) return false;
  return check_clearance(scene, trees, &changed, callbacks);
}

bool SpacetimeDetector::retraverse_changed(const scene::Reconfigurable& scene, const BodyTrees& trees,
                                           const ChangedRanges& changed, const DetectCallbacks& callbacks) {
  stats_ = {};
  if (changed.empty()) return true;
  std::map<std::pair<int, int>, std::vector<std::pair<double, double>>> pair_ranges;
  const int n = static_cast<int>(scene.parts.size());
  for (const auto& [part, ranges] : changed)
    for (const auto& range : ranges)
      for (int q = 0; q < n; ++q)
        if (q != part) pair_ranges[{std::min(part, q), std::max(part, q)}].push_back(range);
  std::vector<PairRange> work;
  std::set<std::pair<int, int>> pairs;
  for (auto& [pair, ranges] : pair_ranges) {
    pairs.insert(pair);
    for (const auto& [t0, t1] : detail::union_of(ranges)) work.push_back({pair.first, pair.second, t0, t1});
  }
  // Drop what the re-traversal will find again: contacts found in a re-traversed step (what a
  // step found stands on its own: its pruning relied on nothing else). The re-traversal starts
  // from those that made their groups' extents.
  const auto retraversed = std::stable_partition(contacts_.begin(), contacts_.end(), [&](const TriangleContact& c) {
    return std::none_of(work.begin(), work.end(), [&](const PairRange& w) {
      return w.a == c.part_a && w.b == c.part_b && c.step_t0 >= w.t0 && c.step_t1 <= w.t1;
    });
  });
  const std::vector<TriangleContact> previous(retraversed, contacts_.end());
  contacts_.erase(retraversed, contacts_.end());
  std::erase_if(containments_, [&](const Containment& c) {
    return pairs.count({std::min(c.inner, c.outer), std::max(c.inner, c.outer)}) > 0;
  });
  return traverse(scene, trees, work, previous, callbacks);
}

bool SpacetimeDetector::traverse(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PairRange>& work,
                                 const std::vector<TriangleContact>& previous, const DetectCallbacks& callbacks) {
  std::vector<detail::TraversalRange> ranges;
  for (const PairRange& w : work) ranges.push_back({w.a, w.b, w.t0, w.t1});
  for (const PartProxy& proxy : proxies_) stats_.proxy_samples += static_cast<long>(proxy.times.size());
  std::vector<TriangleContact> contacts;
  const std::vector<detail::ContactHint> hints = detail::extreme_contacts(previous, FrameGrid(options_.frame));
  if (!detail::traverse_ranges(scene, trees, proxies_, options_, ranges, hints, contacts, stats_, callbacks)) {
    valid_ = false;
    return false;
  }
  const auto kept = static_cast<std::ptrdiff_t>(contacts_.size());  // both runs are sorted
  contacts_.insert(contacts_.end(), contacts.begin(), contacts.end());
  std::inplace_merge(contacts_.begin(), contacts_.begin() + kept, contacts_.end(), detail::contact_less);
  groups_ = detail::group_contacts(contacts_, options_, trees);
  detail::refine_interval_ends(scene, trees, proxies_, options_, groups_, stats_);

  if (options_.detect_containment) {
    const double delta = contact_tolerance(scene, options_.contact);
    // Nesting can only change when surfaces cross: test once per contact-free stretch, at its
    // middle, where the parts' placed boxes must overlap (those are shared by all pairs).
    std::map<std::pair<int, double>, Eigen::AlignedBox3d> boxes;
    const auto box_at = [&](int part, double t) -> const Eigen::AlignedBox3d& {
      auto at = boxes.find({part, t});
      if (at == boxes.end()) at = boxes.emplace(std::pair{part, t}, placed_box(trees, proxies_, part, t)).first;
      return at->second;
    };
    std::set<std::pair<int, int>> pairs;
    for (const PairRange& w : work) pairs.insert({w.a, w.b});
    for (const auto& [a, b] : pairs) {
      std::vector<std::pair<double, double>> touching;
      for (const CollisionInterval& g : groups_)
        if (g.parts[0] == a && g.parts[1] == b && !g.possible) touching.push_back({g.t0, g.t1});
      touching = detail::union_of(std::move(touching));
      std::vector<std::pair<double, double>> free;
      double start = 0;
      for (const auto& [t0, t1] : touching) {
        if (t0 > start) free.push_back({start, t0});
        start = std::max(start, t1);
      }
      if (start < 1) free.push_back({start, 1.0});
      for (const auto& [t0, t1] : free) {
        ++stats_.containment_tests;
        const double t = (t0 + t1) / 2;
        if (!box_at(a, t).intersects(box_at(b, t))) continue;
        for (const auto& [inner, outer] : {std::pair{a, b}, std::pair{b, a}}) {
          if (!nested(scene, trees, proxies_, inner, outer, t, box_at(outer, t), delta)) continue;
          Containment containment{inner, outer, t0, t1, {}};
          // The proxy is linear between its samples: its box over [t0, t1] is that of its
          // positions at t0, t1 and the samples between.
          std::vector<double> corners = {t0, t1};
          for (double s : proxies_[inner].times)
            if (s > t0 && s < t1) corners.push_back(s);
          for (double s : corners)
            containment.box.extend(geometry::bounding_box(detail::proxy_vertices(scene, proxies_[inner], inner, s)));
          containments_.push_back(containment);
          break;
        }
      }
    }
    std::sort(containments_.begin(), containments_.end(), [](const Containment& x, const Containment& y) {
      return std::tie(x.t0, x.inner, x.outer) < std::tie(y.t0, y.inner, y.outer);
    });
  }
  report_progress(callbacks.progress, 1.0);
  return true;
}

}  // namespace reconfig::collision
