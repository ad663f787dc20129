#include "collision/detail/spacetime_traversal.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "collision/detail/frame_contacts.h"
#include "collision/detail/pair_timeline.h"
#include "collision/detail/step_scheduler.h"
#include "collision/detail/traversal_inputs.h"

namespace reconfig::collision::detail {

double traversal_pad(const scene::Reconfigurable& scene, const std::vector<PartProxy>& proxies) {
  double scale = 1;
  for (const scene::Part& part : scene.parts)
    if (part.mesh.V.size() > 0) scale = std::max(scale, part.mesh.V.cwiseAbs().maxCoeff());
  for (const PartProxy& proxy : proxies)
    for (const Eigen::Isometry3d& pose : proxy.poses) scale = std::max(scale, pose.translation().cwiseAbs().maxCoeff());
  return 64 * std::numeric_limits<double>::epsilon() * scale;
}

namespace {

/// The spacetime k-DOP of a part's whole box (its tree's root) over [t0, t1] of its proxy,
/// padded by `pad` and grown by `growth` (`bound_growth`): that of its placements at t0, t1 and at the
/// samples between, as the box's corners move linearly in between (see
/// `TraversalInputs::node_bound`).
template <DopFamily family>
Kdop<family> sweep_bound(const PartProxy& proxy, const BodyTree& tree, double t0, double t1, double pad, double growth) {
  const BodyTree::Node& root = tree.node(BodyTree::kRoot);
  Kdop<family> dop;
  const auto add = [&](double t) {
    const auto [lo, hi] = SampleAxes<family>(proxy_map(proxy, t), t, false).box_extents(root.center, root.half);
    for (int j = 0; j < Kdop<family>::kAxes; ++j) {
      dop.lo[j] = std::min(dop.lo[j], lo[j] - pad);
      dop.hi[j] = std::max(dop.hi[j], hi[j] + pad);
    }
  };
  add(t0);
  add(t1);
  for (double t : proxy.times)
    if (t > t0 && t < t1) add(t);
  if (growth > 0) dop.inflate(growth);
  return dop;
}

}  // namespace

std::vector<std::pair<double, double>> union_of(std::vector<std::pair<double, double>> ranges) {
  std::sort(ranges.begin(), ranges.end());
  std::vector<std::pair<double, double>> merged;
  for (const auto& r : ranges) {
    if (!merged.empty() && r.first <= merged.back().second) merged.back().second = std::max(merged.back().second, r.second);
    else merged.push_back(r);
  }
  return merged;
}

bool contact_less(const TriangleContact& x, const TriangleContact& y) {
  return std::tie(x.t0, x.part_a, x.part_b, x.triangle_a, x.triangle_b, x.t1) <
         std::tie(y.t0, y.part_a, y.part_b, y.triangle_a, y.triangle_b, y.t1);
}

std::vector<TraversalRange> candidate_pairs(const BodyTrees& trees, const std::vector<PartProxy>& proxies,
                                            const scene::Reconfigurable& scene, const DetectorOptions& options) {
  const double pad = traversal_pad(scene, proxies);
  std::vector<TraversalRange> pairs;
  with_dop_family(options.dop, [&]<DopFamily family>() {
    const int n = static_cast<int>(proxies.size());
    std::vector<Kdop<family>> sweeps;
    sweeps.reserve(n);
    for (int p = 0; p < n; ++p)  // as traverse_ranges bounds a range [0, 1]
      sweeps.push_back(sweep_bound<family>(proxies[p], *trees[p], 0.0, 1.0, pad, bound_growth(options, proxies[p])));
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return sweeps[x].lo[0] < sweeps[y].lo[0]; });
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n && sweeps[order[j]].lo[0] <= sweeps[order[i]].hi[0]; ++j)
        if (sweeps[order[i]].overlaps(sweeps[order[j]]))
          pairs.push_back({std::min(order[i], order[j]), std::max(order[i], order[j]), 0.0, 1.0});
  });
  std::sort(pairs.begin(), pairs.end(), [](const TraversalRange& x, const TraversalRange& y) {
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return pairs;
}

bool traverse_ranges(const scene::Reconfigurable& scene, const BodyTrees& trees, const std::vector<PartProxy>& proxies,
                     const DetectorOptions& options, const std::vector<TraversalRange>& ranges,
                     const std::vector<ContactHint>& hints, std::vector<TriangleContact>& contacts, DetectionStats& stats,
                     const DetectCallbacks& callbacks, double given_pad) {
  const double pad = given_pad > 0 ? given_pad : traversal_pad(scene, proxies);
  return with_dop_family(options.dop, [&]<DopFamily family>() {
    // Pairs whose parts' whole sweeps over the range cannot meet are left out at once.
    std::map<std::tuple<int, double, double>, Kdop<family>> sweeps;
    const auto sweep = [&](int part, double t0, double t1) -> const Kdop<family>& {
      auto at = sweeps.find({part, t0, t1});
      if (at == sweeps.end()) {
        const double growth = bound_growth(options, proxies[part]);
        at = sweeps.emplace(std::tuple{part, t0, t1}, sweep_bound<family>(proxies[part], *trees[part], t0, t1, pad, growth)).first;
      }
      return at->second;
    };
    std::vector<PairTimeline> lines;
    for (const TraversalRange& r : ranges) {
      ++stats.bound_tests;
      if (sweep(r.a, r.t0, r.t1).overlaps(sweep(r.b, r.t0, r.t1))) lines.push_back(merged_timeline(proxies, r.a, r.b, r.t0, r.t1));
    }
    const TraversalInputs<family> inputs(scene, trees, proxies, options, std::move(lines), pad);
    return TimelineSearch<family>(inputs, hints, contacts, stats, callbacks).find_contacts();
  });
}

std::vector<CollisionInterval> group_contacts(const std::vector<TriangleContact>& contacts,
                                              const DetectorOptions& options, const BodyTrees& trees) {
  const FrameGrid grid(options.frame);
  std::map<std::tuple<int, int, int>, FrameContacts> frames;  // by parts and frame
  for (const TriangleContact& c : contacts) {
    const auto key = std::tuple{c.part_a, c.part_b, frame_of_contact(grid, c)};
    auto at = frames.find(key);
    if (at == frames.end())
      at = frames.emplace(key, FrameContacts(group_gap(options, smaller_diagonal(*trees[c.part_a], *trees[c.part_b])))).first;
    at->second.add(c);
  }
  std::vector<CollisionInterval> groups;
  for (const auto& [key, frame] : frames) groups.insert(groups.end(), frame.groups().begin(), frame.groups().end());
  std::sort(groups.begin(), groups.end(), [](const CollisionInterval& x, const CollisionInterval& y) {
    return std::tie(x.t0, x.parts, x.t1) < std::tie(y.t0, y.parts, y.t1);
  });
  return groups;
}

Eigen::MatrixX3d proxy_points(const PartProxy& proxy, const Eigen::MatrixX3d& rest, double t) {
  const Affine m = proxy_map(proxy, t);
  return (rest * m.L.transpose()).rowwise() + m.x.transpose();
}

Eigen::MatrixX3d proxy_vertices(const scene::Reconfigurable& scene, const PartProxy& proxy, int part, double t) {
  return proxy_points(proxy, scene.parts[part].mesh.V, t);
}

}  // namespace reconfig::collision::detail
