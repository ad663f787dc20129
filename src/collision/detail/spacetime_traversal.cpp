#include "collision/detail/spacetime_traversal.h"

#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_for_each.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <span>
#include <tuple>

#include "collision/detail/box_grid.h"
#include "collision/detail/frame_contacts.h"
#include "collision/detail/moving_bounds.h"
#include "collision/detail/sample_axes.h"
#include "collision/detail/urgency_queue.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/frame_grid.h"
#include "reconfig/collision/triangle_pair_ccd.h"
#include "reconfig/collision/triangle_touching.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::collision::detail {
namespace {

/// The smaller of two parts' sizes (their box diagonals): the scale of a pair's grouping gap,
/// box grid and urgency.
double smaller_diagonal(const BodyTree& a, const BodyTree& b) {
  const auto diagonal = [](const BodyTree& tree) { return 2 * tree.node(BodyTree::kRoot).half.norm(); };
  return std::min(diagonal(a), diagonal(b));
}

/// How far apart two contacts of a pair of parts in one frame may lie and still be grouped.
double group_gap(const DetectorOptions& options, double smaller_size) { return options.group_gap * smaller_size; }

/// The map a fraction s ∈ [0, 1] of the way from p0 to p1.
Affine between(const Affine& p0, const Affine& p1, double s) { return {(1 - s) * p0.L + s * p1.L, (1 - s) * p0.x + s * p1.x}; }

Affine proxy_map(const PartProxy& proxy, double t) {
  const int k = proxy.step_of(t);
  const double t0 = proxy.times[k], t1 = proxy.times[k + 1];
  const Affine p0{proxy.poses[k].linear(), proxy.poses[k].translation()};
  const Affine p1{proxy.poses[k + 1].linear(), proxy.poses[k + 1].translation()};
  if (t <= t0) return p0;
  if (t >= t1) return p1;
  return between(p0, p1, (t - t0) / (t1 - t0));
}

}  // namespace

double traversal_pad(const scene::Reconfigurable& scene, const std::vector<PartProxy>& proxies) {
  double scale = 1;
  for (const scene::Part& part : scene.parts)
    if (part.mesh.V.size() > 0) scale = std::max(scale, part.mesh.V.cwiseAbs().maxCoeff());
  for (const PartProxy& proxy : proxies)
    for (const Eigen::Isometry3d& pose : proxy.poses) scale = std::max(scale, pose.translation().cwiseAbs().maxCoeff());
  return 64 * std::numeric_limits<double>::epsilon() * scale;
}

namespace {

/// Both parts of a pair placed at the merged sample times of their proxies over a range:
/// on every step between consecutive times both parts' vertices move linearly.
struct PairTimeline {
  int a = 0, b = 0;
  std::vector<double> times;
  std::vector<Affine> maps[2];
  bool moving[2] = {false, false};  ///< some map differs from the first

  /// The step [times[k], times[k + 1]] holding t (the first or last step outside the range),
  /// as `PartProxy::step_of`.
  int step_of(double t) const {
    const int k = static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    return std::clamp(k, 0, static_cast<int>(times.size()) - 2);
  }
};

PairTimeline make_timeline(const std::vector<PartProxy>& proxies, int a, int b, double t0, double t1) {
  PairTimeline line;
  line.a = a;
  line.b = b;
  std::vector<double> times = {t0, t1};
  for (int part : {a, b})
    for (double t : proxies[part].times)
      if (t > t0 && t < t1) times.push_back(t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  line.times = times;
  for (int side = 0; side < 2; ++side) {
    const PartProxy& proxy = proxies[side == 0 ? a : b];
    for (double t : times) line.maps[side].push_back(proxy_map(proxy, t));
    for (const Affine& m : line.maps[side]) line.moving[side] = line.moving[side] || !(m == line.maps[side][0]);
  }
  return line;
}

/// Parts of fewer triangles are bounded by their nodes' boxes alone: their trees are shallow,
/// so tighter bounds prune little below them, and cost more than they save (on the kitchen,
/// whose parts have at most 380 triangles, 25 % more instructions for 8–12 % fewer bound tests;
/// on the 650-triangle eights, 28 % fewer instructions).
constexpr int kTightenedTriangles = 512;

/// The spacetime k-DOP of a part's whole box (its tree's root) over [t0, t1] of its proxy,
/// padded by `pad` and grown by `deviation`: that of its placements at t0, t1 and at the
/// samples between, as the box's corners move linearly in between (see `Traversal::bound`).
template <DopFamily family>
Kdop<family> sweep_bound(const PartProxy& proxy, const BodyTree& tree, double t0, double t1, double pad, double deviation) {
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
  if (deviation > 0) dop.inflate(deviation);
  return dop;
}

Eigen::AlignedBox3d inflated(Eigen::AlignedBox3d box, double by) {
  box.min().array() -= by;
  box.max().array() += by;
  return box;
}

struct WorkItem {
  int pair = 0;
  int node_a = 0, node_b = 0;
  int s0 = 0, s1 = 0;  ///< sample range of the pair timeline (s1 > s0)
};

/// The groups of the contacts found in one proxy step, per frame the step overlaps.
using StepGroups = std::vector<FrameContacts>;

/// Everything the traversal reads, shared by all threads.
template <DopFamily family>
struct Traversal {
  using Dop = Kdop<family>;
  static constexpr int K = Dop::kAxes;

  const scene::Reconfigurable& scene;
  const BodyTrees& trees;
  const std::vector<PartProxy>& proxies;
  const DetectorOptions& options;
  const FrameGrid grid;
  std::vector<PairTimeline> lines;
  /// Per pair, side and sample: the axes seen from the part's rest frame.
  std::vector<std::array<std::vector<SampleAxes<family>, Eigen::aligned_allocator<SampleAxes<family>>>, 2>> axes;
  double pad = 0;  ///< absolute padding against rounding in bound arithmetic (`traversal_pad`)
  double contact = 0;  ///< the contact tolerance δ (`contact_tolerance`)
  std::vector<double> size;  ///< per pair: the smaller part's size (box diagonal)
  /// Per pair and step: the frames the step overlaps (`FrameGrid::frames_overlapping`).
  std::vector<std::vector<std::pair<int, int>>> step_frames;

  Traversal(const scene::Reconfigurable& s, const BodyTrees& t, const std::vector<PartProxy>& p,
            const DetectorOptions& o, std::vector<PairTimeline> l, double rounding)
      : scene(s), trees(t), proxies(p), options(o), grid(o.frame), lines(std::move(l)), pad(rounding),
        contact(contact_tolerance(s, o.contact)) {
    axes.resize(lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i)
      for (int side = 0; side < 2; ++side)
        for (std::size_t k = 0; k < lines[i].times.size(); ++k) {
          const Affine& map = lines[i].maps[side][k];
          auto& samples = axes[i][side];
          if (k > 0 && samples.back().map.L == map.L) samples.emplace_back(samples.back(), map, lines[i].times[k]);
          else samples.emplace_back(map, lines[i].times[k], tree(static_cast<int>(i), side).triangle_count() >= kTightenedTriangles);
        }
    for (std::size_t i = 0; i < lines.size(); ++i) {
      size.push_back(smaller_diagonal(tree(static_cast<int>(i), 0), tree(static_cast<int>(i), 1)));
      step_frames.emplace_back();
      for (std::size_t k = 0; k + 1 < lines[i].times.size(); ++k)
        step_frames.back().push_back(grid.frames_overlapping(lines[i].times[k], lines[i].times[k + 1]));
    }
  }

  const geometry::Mesh& mesh(int pair, int side) const { return scene.parts[side == 0 ? lines[pair].a : lines[pair].b].mesh; }
  const BodyTree& tree(int pair, int side) const { return *trees[side == 0 ? lines[pair].a : lines[pair].b]; }

  /// The node's spacetime k-DOP over samples [s0, s1], padded against rounding (and grown by
  /// the proxy's deviation in conservative mode); `ends`, if given, receives its k-DOPs at
  /// samples s0 and s1, padded (and grown) alike.
  Dop bound(int pair, int side, int node_index, int s0, int s1, std::array<Dop, 2>* ends = nullptr) const {
    const BodyTree::Node& node = tree(pair, side).node(node_index);
    const auto& samples = axes[pair][side];
    Dop dop;
    using Axes = Eigen::Matrix<double, K, 1>;
    Axes lo = Axes::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    const auto add = [&](int s, const Axes& low, const Axes& high) {
      lo = lo.cwiseMin(low);
      hi = hi.cwiseMax(high);
      if (ends && (s == s0 || s == s1)) {
        Dop& end = (*ends)[s == s0 ? 0 : 1];
        for (int j = 0; j < K; ++j) {
          end.lo[j] = low[j] - pad;
          end.hi[j] = high[j] + pad;
        }
      }
    };
    if (node.leaf()) {
      const geometry::Mesh& m = mesh(pair, side);
      const Eigen::Vector3d v0 = m.V.row(m.F(node.triangle, 0)), v1 = m.V.row(m.F(node.triangle, 1)),
                            v2 = m.V.row(m.F(node.triangle, 2));
      for (int s = s0; s <= s1; ++s) {
        const Axes p0 = samples[s].point_values(v0), p1 = samples[s].point_values(v1), p2 = samples[s].point_values(v2);
        add(s, p0.cwiseMin(p1).cwiseMin(p2), p0.cwiseMax(p1).cwiseMax(p2));
      }
    } else {
      const BodyTree::DiagonalSlack& slack = tree(pair, side).diagonal_slack(node_index);
      for (int s = s0; s <= s1; ++s) {
        const auto [low, high] = samples[s].node_extents(node, slack);
        add(s, low, high);
      }
    }
    for (int j = 0; j < K; ++j) {
      dop.lo[j] = lo[j] - pad;
      dop.hi[j] = hi[j] + pad;
    }
    const double deviation = options.conservative ? proxies[side == 0 ? lines[pair].a : lines[pair].b].deviation : 0.0;
    if (deviation > 0) {
      dop.inflate(deviation);
      if (ends)
        for (Dop& end : *ends) end.inflate(deviation);
    }
    return dop;
  }

  /// The spatial box of a node over the time range [t0, t1] of the pair's timeline, padded
  /// like `bound` (and grown by `deviation`): that of its placements at t0, t1 and the samples
  /// between, as it moves linearly in between.
  Eigen::AlignedBox3d box_between(int pair, int side, int node_index, double t0, double t1, double deviation) const {
    const PairTimeline& line = lines[pair];
    const BodyTree::Node& node = tree(pair, side).node(node_index);
    const geometry::Mesh& m = mesh(pair, side);
    Eigen::AlignedBox3d box;
    const auto extend = [&](const Affine& map) {
      if (node.leaf()) {
        for (int c = 0; c < 3; ++c) box.extend(map(m.V.row(m.F(node.triangle, c))));
      } else {
        const Eigen::Vector3d center = map(node.center), reach = map.L.cwiseAbs() * node.half;
        box.extend(center - reach);
        box.extend(center + reach);
      }
    };
    const auto at = [&](double t) {
      const int s = line.step_of(t);
      const double mu = std::clamp((t - line.times[s]) / (line.times[s + 1] - line.times[s]), 0.0, 1.0);
      return between(line.maps[side][s], line.maps[side][s + 1], mu);
    };
    extend(at(t0));
    extend(at(t1));
    for (std::size_t k = 0; k < line.times.size(); ++k)
      if (line.times[k] > t0 && line.times[k] < t1) extend(line.maps[side][k]);
    return inflated(box, pad + deviation);
  }

  double gap(int pair) const { return group_gap(options, size[pair]); }
  /// The cell of the grid a pair's contact boxes are rounded out to.
  double cell(int pair) const { return options.box_resolution * size[pair]; }

  MovingTriangle corners(int pair, int side, int triangle, int s) const {
    const geometry::Mesh& m = mesh(pair, side);
    const Affine& map = lines[pair].maps[side][s];
    return {map(m.V.row(m.F(triangle, 0))), map(m.V.row(m.F(triangle, 1))), map(m.V.row(m.F(triangle, 2)))};
  }
};

/// The bounds of the nodes one thread met last, by (pair, side, node, sample range): the two
/// children of a split item share the node that was not split, whose bound would otherwise be
/// computed again. Direct-mapped per side: a newer bound of the same side may take its slot.
template <DopFamily family>
class BoundCache {
 public:
  using Dop = Kdop<family>;
  struct Bound {
    Dop dop;
    std::array<Dop, 2> ends;  ///< at the range's ends (single steps only)
  };

  /// The node's bound over [s0, s1] (`Traversal::bound`, with the ends for a single step),
  /// valid until the next call for the same side.
  const Bound& get(const Traversal<family>& tr, int pair, int side, int node, int s0, int s1) {
    const Key key{pair, node, s0, s1};
    Slot& slot = slots_[side][slot_of(key)];
    if (!(slot.key == key)) {
      slot.key = key;
      slot.bound.dop = tr.bound(pair, side, node, s0, s1, s1 - s0 == 1 ? &slot.bound.ends : nullptr);
    }
    return slot.bound;
  }

 private:
  struct Key {
    int pair = -1, node = 0, s0 = 0, s1 = 0;
    bool operator==(const Key&) const = default;
  };
  struct Slot {
    Key key;
    Bound bound;
  };
  static constexpr int kSlotBits = 8;
  static std::size_t slot_of(const Key& k) {
    std::uint64_t h = static_cast<std::uint32_t>(k.node) * 0x9E3779B97F4A7C15ull;
    h ^= (static_cast<std::uint64_t>(k.s0) << 32 | static_cast<std::uint32_t>(k.s1)) * 0xC2B2AE3D27D4EB4Full;
    h ^= static_cast<std::uint64_t>(k.pair) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(h >> (64 - kSlotBits));
  }
  std::array<std::vector<Slot>, 2> slots_{std::vector<Slot>(std::size_t{1} << kSlotBits),
                                          std::vector<Slot>(std::size_t{1} << kSlotBits)};
};

double spatial_extent(const auto& dop) {
  return std::max({dop.hi[0] - dop.lo[0], dop.hi[1] - dop.lo[1], dop.hi[2] - dop.lo[2]});
}

/// The narrow phase refines a step down to this many equal pieces (dyadic: they nest within the
/// `kCullPieces`), and reports a piece whole when a contact event lies in it.
constexpr int kNarrowPieces = 32;

/// Two leaves over at most this many steps are bounded step by step.
constexpr int kStepwiseLeafSteps = 8;

/// A contact and the pair timeline it was found on.
struct LineContact {
  int line = 0;
  TriangleContact contact;
};

/// What one work item reads of the contacts found so far, and where its own contacts go.
/// Pruning relies only on the groups of contacts found in the same proxy step, so that what a
/// step finds stands on its own (an update drops and re-finds whole steps).
struct ItemContext {
  /// The groups found so far in one step of a pair timeline, or null if none.
  std::function<const StepGroups*(int line, int step)> step_groups;
  std::vector<LineContact>& contacts;  ///< contacts the item finds, clipped to frames
  DetectionStats& stats;
};

/// The frame a contact clipped to frames lies in.
int frame_of_contact(const FrameGrid& grid, const TriangleContact& c) { return grid.frame_of((c.t0 + c.t1) / 2); }

/// The frames an item may report contacts in: those its time range overlaps for a positive
/// time (an instant contact at its start on a frame boundary belongs to the frame on the left,
/// where the previous step reports it).
template <DopFamily family>
std::pair<int, int> item_frames(const Traversal<family>& tr, const WorkItem& item) {
  return {tr.step_frames[item.pair][item.s0].first, tr.step_frames[item.pair][item.s1 - 1].second};
}

/// How far the contacts the item could find might lie outside the groups of its step (for an
/// item over one step; infinite for longer items), given that it can find contacts only during
/// [from, to] (within its range): in each frame k, within [from, to] clipped to the frame,
/// [t0, t1], and within `box_between(t0, t1)`, the box where the item's contacts over that
/// time can lie (empty if the two nodes cannot meet then), the `FrameContacts::protrusion` of
/// that box; the largest over the frames. 0 if every contact the item could find would fall
/// inside a group, or there is none to find. The frames after one whose protrusion reaches
/// `enough` are left out (a caller asking only whether it is 0 passes the least double).
template <DopFamily family>
double protrusion(const Traversal<family>& tr, const WorkItem& item, const ItemContext& context, const auto& box_between,
                  double from, double to, double enough = std::numeric_limits<double>::infinity()) {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  const auto [first, last] = item_frames(tr, item);  // `first`: that of the item's step groups
  const StepGroups* groups = item.s1 - item.s0 == 1 ? context.step_groups(item.pair, item.s0) : nullptr;
  double largest = 0;
  for (int k = first; k <= last; ++k) {
    const double t0 = std::max(from, tr.grid.lo(k)), t1 = std::min(to, tr.grid.hi(k));
    if (t0 > t1) continue;
    const Eigen::AlignedBox3d box = box_between(t0, t1);
    if (box.isEmpty()) continue;
    if (tr.options.all_contacts || !groups) return kUnknown;
    largest = std::max(largest, (*groups)[k - first].protrusion(t0, t1, box));
    if (largest >= enough) return largest;
  }
  return largest;
}

/// Processes one work item: prunes it, splits it into `next`, or runs the narrow phase.
/// @return the item's `protrusion` when it was split (its children's urgency until they are
///         looked at), else 0
template <DopFamily family>
double process(const Traversal<family>& tr, const WorkItem& item, std::vector<WorkItem>& next, const ItemContext& context,
               BoundCache<family>& bounds) {
  DetectionStats& stats = context.stats;
  const PairTimeline& line = tr.lines[item.pair];
  const BodyTree::Node& na = tr.tree(item.pair, 0).node(item.node_a);
  const BodyTree::Node& nb = tr.tree(item.pair, 1).node(item.node_b);
  const bool single_step = item.s1 - item.s0 == 1;
  const double deviation_a = tr.options.conservative ? tr.proxies[line.a].deviation : 0.0;
  const double deviation_b = tr.options.conservative ? tr.proxies[line.b].deviation : 0.0;
  const Kdop<family>* da = nullptr;  // the nodes' k-DOPs over the range (in the bound cache)
  const Kdop<family>* db = nullptr;
  double urgency = std::numeric_limits<double>::infinity();
  if (!(na.leaf() && nb.leaf() && single_step)) {  // that case is culled by `meeting_pieces`, tighter
    ++stats.bound_tests;
    // The k-DOPs over the range, and at the ends of a single step.
    const auto& bound_a = bounds.get(tr, item.pair, 0, item.node_a, item.s0, item.s1);
    const auto& bound_b = bounds.get(tr, item.pair, 1, item.node_b, item.s0, item.s1);
    da = &bound_a.dop;
    db = &bound_b.dop;
    const std::array<Kdop<family>, 2>& ends_a = bound_a.ends;
    const std::array<Kdop<family>, 2>& ends_b = bound_b.ends;
    if (!da->overlaps(*db)) return 0;
    const double step_t0 = line.times[item.s0], step_t1 = line.times[item.s1];
    double meet_t0 = step_t0, meet_t1 = step_t1;  // when the nodes may meet
    if (single_step) {
      const auto [mu0, mu1] = meeting_range(ends_a, ends_b);
      if (mu0 > mu1) return 0;
      // The narrow phase may report a contact over a whole piece of its grid, beyond the times
      // the triangles meet: the item's contacts lie within the pieces that [mu0, mu1] touches.
      const double piece0 = std::floor(mu0 * kNarrowPieces), piece1 = std::ceil(mu1 * kNarrowPieces);
      if (piece0 > 0) meet_t0 = step_t0 + piece0 / kNarrowPieces * (step_t1 - step_t0);
      if (piece1 < kNarrowPieces) meet_t1 = std::min(step_t1, step_t0 + piece1 / kNarrowPieces * (step_t1 - step_t0));
    }
    const auto box_between = [&](double t0, double t1) {
      if (t0 <= step_t0 && t1 >= step_t1) return spatial_box(*da).intersection(spatial_box(*db));
      if (single_step) {
        // Within one step a node's box at a time lies within the interpolation of its boxes at
        // the step's ends (its center moves linearly, and its reach |L|·half is convex in time),
        // so over [t0, t1] within the hull of those interpolations at t0 and t1.
        const double mu0 = std::max(0.0, (t0 - step_t0) / (step_t1 - step_t0)), mu1 = std::min(1.0, (t1 - step_t0) / (step_t1 - step_t0));
        const auto sweep = [&](const std::array<Kdop<family>, 2>& ends) {
          const Eigen::AlignedBox3d box0 = spatial_box(ends[0]), box1 = spatial_box(ends[1]);
          const auto lerp = [&](double mu) {
            return Eigen::AlignedBox3d((1 - mu) * box0.min() + mu * box1.min(), (1 - mu) * box0.max() + mu * box1.max());
          };
          return lerp(mu0).extend(lerp(mu1));
        };
        return inflated(sweep(ends_a), tr.pad).intersection(inflated(sweep(ends_b), tr.pad));
      }
      return tr.box_between(item.pair, 0, item.node_a, t0, t1, deviation_a)
          .intersection(tr.box_between(item.pair, 1, item.node_b, t0, t1, deviation_b));
    };
    urgency = protrusion(tr, item, context, box_between, meet_t0, meet_t1);
    if (urgency == 0) {
      ++stats.pruned;
      return 0;
    }
  }
  const auto push = [&](int node_a, int node_b, int s0, int s1) { next.push_back({item.pair, node_a, node_b, s0, s1}); };
  const auto split_time = [&] {
    const int middle = (item.s0 + item.s1) / 2;
    push(item.node_a, item.node_b, item.s0, middle);
    push(item.node_a, item.node_b, middle, item.s1);
  };
  if (na.leaf() && nb.leaf()) {
    // The narrow phase of the two triangles over samples [s0, s1]: one step, or a range over
    // which both hold still.
    const auto leaves = [&](int s0, int s1) {
      const double t0 = line.times[s0], t1 = line.times[s1];
      const auto [first_frame, last_frame] = item_frames(tr, {item.pair, item.node_a, item.node_b, s0, s1});
      const auto time_at = [&](double mu) { return mu == 0 ? t0 : mu == 1 ? t1 : t0 + mu * (t1 - t0); };
      const auto mu_at = [&](double t) { return (t - t0) / (t1 - t0); };
      // Reports, as one contact per frame, a run of touching pieces of the step (step
      // parameters) in which the triangles intersect: its time clipped to the frame, and the
      // union over its pieces of where the triangles may meet during each (the box where they
      // meet over a union of pieces would be larger, and depend on which pieces are reported).
      const auto emit = [&](const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                            const MovingTriangle& b1, std::span<const TimeInterval> run, bool possible) {
        // Where the triangles (or, for a possible contact, the true motions within the
        // deviations) may meet over step parameters [mu_lo, mu_hi]; nowhere if the boxes miss
        // each other there, which happens where a piece reported whole is clipped to a frame.
        // The padding absorbs the rounding of the boxes.
        const auto meeting_box = [&](double mu_lo, double mu_hi) {
          const double grow_a = (possible ? deviation_a : 0.0) + tr.pad, grow_b = (possible ? deviation_b : 0.0) + tr.pad;
          const Eigen::AlignedBox3d box_a = triangle_box_at(a0, a1, mu_lo, mu_hi);
          const Eigen::AlignedBox3d box_b = triangle_box_at(b0, b1, mu_lo, mu_hi);
          Eigen::AlignedBox3d box = possible ? Eigen::AlignedBox3d() : box_a.intersection(box_b);
          if (box.isEmpty()) box = inflated(box_a, grow_a).intersection(inflated(box_b, grow_b));
          return box;
        };
        // The contact over [lo, hi] (within one frame and the run).
        const auto report = [&](double lo, double hi) {
          Eigen::AlignedBox3d box;
          for (const TimeInterval& piece : run) {
            const double p_lo = time_at(piece.lo), p_hi = time_at(piece.hi);
            if (p_hi < lo || p_lo > hi) continue;
            box.extend(meeting_box(p_lo < lo ? mu_at(lo) : piece.lo, p_hi > hi ? mu_at(hi) : piece.hi));
          }
          if (box.isEmpty()) return;
          context.contacts.push_back(
              {item.pair, {line.a, na.triangle, line.b, nb.triangle, lo, hi, round_out(box, tr.cell(item.pair)), possible, t0, t1}});
        };
        const double ta = time_at(run.front().lo), tb = time_at(run.back().hi);
        if (ta == tb) {
          const int k = tr.grid.frame_of(ta);
          if (k >= first_frame && k <= last_frame) report(ta, ta);
          return;
        }
        const auto [f0, f1] = tr.grid.frames_overlapping(ta, tb);
        for (int k = std::max(f0, first_frame); k <= std::min(f1, last_frame); ++k) {
          const double lo = std::max(ta, tr.grid.lo(k)), hi = std::min(tb, tr.grid.hi(k));
          if (hi > lo) report(lo, hi);
        }
      };
      const auto emit_one = [&](const MovingTriangle& a0, const MovingTriangle& a1, const MovingTriangle& b0,
                                const MovingTriangle& b1, double mu0, double mu1, bool possible) {
        const TimeInterval piece{mu0, mu1};
        emit(a0, a1, b0, b1, std::span(&piece, 1), possible);
      };
      if (s1 - s0 == 1) {
        const MovingTriangle a0 = tr.corners(item.pair, 0, na.triangle, s0);
        const MovingTriangle a1 = tr.corners(item.pair, 0, na.triangle, s1);
        const MovingTriangle b0 = tr.corners(item.pair, 1, nb.triangle, s0);
        const MovingTriangle b1 = tr.corners(item.pair, 1, nb.triangle, s1);
        const WorkItem step{item.pair, item.node_a, item.node_b, s0, s1};
        const auto box_between = [&](double ta, double tb) {
          const double mu0 = ta <= t0 ? 0.0 : mu_at(ta), mu1 = tb >= t1 ? 1.0 : mu_at(tb);
          return inflated(triangle_box_at(a0, a1, mu0, mu1), deviation_a + tr.pad)
              .intersection(inflated(triangle_box_at(b0, b1, mu0, mu1), deviation_b + tr.pad));
        };
        const unsigned meeting = meeting_pieces<family>(a0, a1, b0, b1, deviation_a + deviation_b + 2 * tr.pad);
        if (meeting == 0) return;
        // Contacts can only lie within the pieces where the triangles may meet.
        const double from = time_at(static_cast<double>(std::countr_zero(meeting)) / kCullPieces);
        const double to = time_at(static_cast<double>(std::bit_width(meeting)) / kCullPieces);
        constexpr double kAny = std::numeric_limits<double>::denorm_min();  // whether it sticks out at all
        if (protrusion(tr, step, context, box_between, from, to, kAny) == 0) {
          ++stats.pruned;
          return;
        }
        ++stats.narrow_phase;
        TrianglePairCcdRequest request;
        request.a_start = a0;
        request.a_end = a1;
        request.b_start = b0;
        request.b_end = b1;
        request.time_tolerance = 1.0 / kNarrowPieces;  // of the step: pieces with a contact event are reported whole below that
        request.distance_tolerance = 1e-4;
        // The pieces come back unmerged, and a contact's box is the union of its pieces'
        // (`emit`), so that what a piece adds does not depend on the pieces next to it; then
        // the pieces of the step where whatever the triangles meet in would fall inside the
        // groups can be left out. (Not in conservative mode: there the absence of contacts
        // matters too.)
        request.merge_pieces = false;
        if (!tr.options.conservative)
          request.relevant = [&](double lo, double hi) {
            return protrusion(tr, step, context, box_between, time_at(lo), time_at(hi), kAny) > 0;
          };
        const TrianglePairCcdResult spans = triangle_pair_ccd(request);
        stats.narrow_pieces += spans.pieces;
        stats.contact_tests += spans.contact_tests;
        // Where the triangles only touch within δ, they do not collide (`triangle_touching.h`).
        const std::vector<TimeInterval> pieces =
            tr.options.touching_collides ? spans.intervals
                                         : interference_pieces(a0, a1, b0, b1, spans.intervals, tr.contact);
        for (std::size_t first = 0, end = 1; first < pieces.size(); first = end++) {
          while (end < pieces.size() && pieces[end].lo <= pieces[end - 1].hi) ++end;  // a run of touching pieces
          emit(a0, a1, b0, b1, std::span(pieces).subspan(first, end - first), false);
        }
        if (!spans.any() && tr.options.conservative) {
          // The proxies miss, but the true motions stray up to the deviations from them: report
          // the sixteenths of the step where the triangles' spacetime k-DOPs, so inflated, meet.
          const double reach = deviation_a + deviation_b + tr.pad;
          constexpr int kPieces = 16;
          for (int k = 0; k < kPieces; ++k) {
            const double lo = static_cast<double>(k) / kPieces, hi = static_cast<double>(k + 1) / kPieces;
            Kdop<family> dop_a, dop_b;
            for (double mu : {lo, hi})
              for (int c = 0; c < 3; ++c) {
                dop_a.extend((1 - mu) * a0[c] + mu * a1[c], mu);
                dop_b.extend((1 - mu) * b0[c] + mu * b1[c], mu);
              }
            dop_a.inflate(reach);
            if (dop_a.overlaps(dop_b)) emit_one(a0, a1, b0, b1, lo, hi, true);
          }
        }
        return;
      }
      if (!line.moving[0] && !line.moving[1]) {  // both hold still: one static test decides
        ++stats.narrow_phase;
        const MovingTriangle a = tr.corners(item.pair, 0, na.triangle, s0);
        const MovingTriangle b = tr.corners(item.pair, 1, nb.triangle, s0);
        if (geometry::triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]) &&
            (tr.options.touching_collides || !triangles_touch(a, b, tr.contact)))
          emit_one(a, a, b, b, 0, 1, false);
      }
    };
    if (single_step || (!line.moving[0] && !line.moving[1])) {
      leaves(item.s0, item.s1);
      return 0;
    }
    // Over a few steps, bound each step on its own: halving the range again and again would
    // bound every half over all its samples. Long ranges are halved first, as a range where the
    // triangles meet nowhere is then dropped with one test.
    if (item.s1 - item.s0 > kStepwiseLeafSteps) {
      split_time();
      return urgency;
    }
    for (int s = item.s0; s < item.s1; ++s) {
      ++stats.bound_tests;
      if (tr.bound(item.pair, 0, item.node_a, s, s + 1).overlaps(tr.bound(item.pair, 1, item.node_b, s, s + 1)))
        leaves(s, s + 1);
    }
    return 0;
  }
  // Split the dimension that makes the bounds loose: time when the motion over the range
  // sweeps further than the nodes are large, else the larger node.
  const double size_a = 2 * na.half.maxCoeff(), size_b = 2 * nb.half.maxCoeff();
  const double sweep = std::max(spatial_extent(*da) - size_a, spatial_extent(*db) - size_b);
  if (!single_step && sweep > std::min(size_a, size_b)) {
    split_time();
  } else if (!na.leaf() && (nb.leaf() || size_a >= size_b)) {
    push(na.left, item.node_b, item.s0, item.s1);
    push(na.right, item.node_b, item.s0, item.s1);
  } else {
    push(item.node_a, nb.left, item.s0, item.s1);
    push(item.node_a, nb.right, item.s0, item.s1);
  }
  return urgency;
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


namespace {

/// Work items per task in the breadth-first phase.
constexpr std::size_t kBreadthFirstGrain = 4;

/// Steps done between two progress reports (and previews) in the depth-first phase.
constexpr std::size_t kStepsPerReport = 16;

/// The groups of the contacts found so far, per pair timeline and proxy step: what pruning
/// relies on.
template <DopFamily family>
class FoundSteps {
 public:
  explicit FoundSteps(const Traversal<family>& tr) : tr_(tr), groups_(tr.lines.size()) {
    for (std::size_t i = 0; i < tr.lines.size(); ++i) groups_[i].resize(tr.lines[i].times.size() - 1);
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
    const std::vector<double>& times = tr_.lines[line].times;
    const int step = static_cast<int>(std::lower_bound(times.begin(), times.end(), contact.step_t0) - times.begin());
    if (step + 1 >= static_cast<int>(times.size()) || times[step + 1] != contact.step_t1) return;
    const auto [first, last] = tr_.grid.frames_overlapping(times[step], times[step + 1]);
    StepGroups& groups = groups_[line][step];
    if (groups.empty()) groups.assign(last - first + 1, FrameContacts(tr_.gap(line), false));
    const int frame = frame_of_contact(tr_.grid, contact);
    assert(frame >= first && frame <= last);  // a step reports contacts in its own frames only
    groups[frame - first].add(contact);
  }

 private:
  const Traversal<family>& tr_;
  std::vector<std::vector<StepGroups>> groups_;
};

/// Leaf pairs whose narrow phase runs first, per pair timeline and step.
using StepLeaves = std::map<std::pair<int, int>, std::vector<std::pair<int, int>>>;

/// Sorts a step's leaf pairs and drops repeats (the order they run in is then fixed).
void tidy(std::vector<std::pair<int, int>>& pairs) {
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

/// The leaves of a hint's two triangles in the trees of pair timeline `line`.
template <DopFamily family>
std::pair<int, int> leaf_pair(const Traversal<family>& tr, int line, const ContactHint& hint) {
  return {tr.tree(line, 0).leaf_of(hint.triangle_a), tr.tree(line, 1).leaf_of(hint.triangle_b)};
}

/// The leaf pairs of the hints, in the step that holds each hint's time.
template <DopFamily family>
StepLeaves hinted_leaves(const Traversal<family>& tr, const std::vector<ContactHint>& hints) {
  StepLeaves leaves;
  if (tr.options.all_contacts) return leaves;  // nothing is pruned: no order is better than another
  std::multimap<std::pair<int, int>, int> lines_of;  // the pair timelines of each pair of parts
  for (int i = 0; i < static_cast<int>(tr.lines.size()); ++i) lines_of.emplace(std::pair{tr.lines[i].a, tr.lines[i].b}, i);
  for (const ContactHint& hint : hints) {
    const auto [begin, end] = lines_of.equal_range({hint.part_a, hint.part_b});
    for (auto at = begin; at != end; ++at) {
      const int i = at->second;
      const PairTimeline& line = tr.lines[i];
      if (hint.t < line.times.front() || hint.t > line.times.back()) continue;
      leaves[{i, line.step_of(hint.t)}].push_back(leaf_pair(tr, i, hint));
    }
  }
  for (auto& [step, pairs] : leaves) tidy(pairs);
  return leaves;
}

/// The leaf pairs of the contacts that made the extents of a neighbor's groups, found there,
/// in the frames it shares with step `step` of pair timeline `line`: contacts persist from
/// step to step (a drawer sliding past a door meets the same faces), so those pairs most
/// likely make the extents of the step's groups there too.
template <DopFamily family>
std::vector<std::pair<int, int>> neighbor_leaves(const Traversal<family>& tr, int line, int step,
                                                 const std::vector<LineContact>& found) {
  std::vector<std::pair<int, int>> leaves;
  if (tr.options.all_contacts) return leaves;
  const auto [first, last] = tr.step_frames[line][step];
  std::vector<TriangleContact> shared;
  for (const LineContact& c : found)
    if (const int frame = frame_of_contact(tr.grid, c.contact); frame >= first && frame <= last) shared.push_back(c.contact);
  for (const ContactHint& hint : extreme_contacts(shared, tr.grid)) leaves.push_back(leaf_pair(tr, line, hint));
  return leaves;
}

template <DopFamily family>
bool run_traversal(const Traversal<family>& tr, const std::vector<ContactHint>& hints, std::vector<TriangleContact>& contacts,
                   DetectionStats& stats, const DetectCallbacks& callbacks) {
  FoundSteps<family> found(tr);
  StepLeaves hinted = hinted_leaves(tr, hints);
  tbb::enumerable_thread_specific<BoundCache<family>> bound_caches;
  const auto step_groups = [&](int line, int step) { return found.of(line, step); };
  std::vector<WorkItem> level;
  int max_depth = 1, max_steps = 1;
  for (int i = 0; i < static_cast<int>(tr.lines.size()); ++i) {
    const int steps = static_cast<int>(tr.lines[i].times.size()) - 1;
    level.push_back({i, BodyTree::kRoot, BodyTree::kRoot, 0, steps});
    max_depth = std::max(max_depth, tr.tree(i, 0).depth() + tr.tree(i, 1).depth());
    max_steps = std::max(max_steps, steps);
  }
  const auto contact_ranges = [&] {
    std::vector<std::pair<double, double>> ranges;
    for (const TriangleContact& c : contacts) ranges.push_back({c.t0, c.t1});
    return ranges;
  };

  // Breadth first: coarse time extents level by level.
  const double expected_levels = max_depth + std::ceil(std::log2(max_steps)) + 1;
  int depth = 0;
  while (!level.empty() && level.size() < tr.options.breadth_first_items) {
    ++depth;
    tbb::combinable<std::vector<WorkItem>> next_parts;
    tbb::combinable<std::vector<LineContact>> found_parts;
    tbb::combinable<DetectionStats> stat_parts;
    const auto run = [&](std::size_t begin, std::size_t end) {
      auto& next = next_parts.local();
      const ItemContext context{step_groups, found_parts.local(), stat_parts.local()};
      for (std::size_t i = begin; i < end; ++i) process(tr, level[i], next, context, bound_caches.local());
    };
    // Items of these first levels span many steps (a bound over every sample of their range
    // each): worth a task of a few.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, level.size(), kBreadthFirstGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) { run(r.begin(), r.end()); });
    std::vector<WorkItem> next;
    next_parts.combine_each([&](const std::vector<WorkItem>& part) { next.insert(next.end(), part.begin(), part.end()); });
    std::vector<LineContact> batch;
    found_parts.combine_each([&](const std::vector<LineContact>& part) { batch.insert(batch.end(), part.begin(), part.end()); });
    // In an order that does not depend on the threads.
    std::sort(batch.begin(), batch.end(), [](const LineContact& x, const LineContact& y) {
      return contact_less(x.contact, y.contact) || (!contact_less(y.contact, x.contact) && x.line < y.line);
    });
    for (const LineContact& c : batch) {
      found.add(c.line, c.contact);
      contacts.push_back(c.contact);
    }
    stat_parts.combine_each([&](const DetectionStats& s) { stats += s; });
    stats.levels = depth;
    if (callbacks.preview) {
      std::vector<std::pair<double, double>> ranges = contact_ranges();
      for (const WorkItem& item : next) ranges.push_back({tr.lines[item.pair].times[item.s0], tr.lines[item.pair].times[item.s1]});
      callbacks.preview({depth, union_of(std::move(ranges))});
    }
    if (!report_progress(callbacks.progress, std::min(0.5, 0.5 * depth / expected_levels))) return false;
    std::sort(next.begin(), next.end(), [](const WorkItem& x, const WorkItem& y) {
      return std::tie(x.pair, x.s0, x.node_a, x.node_b, x.s1) < std::tie(y.pair, y.s0, y.node_a, y.node_b, y.s1);
    });
    level = std::move(next);
  }
  if (!level.empty()) {
    // Depth first, one step of one pair timeline at a time (the steps in parallel): contacts
    // found grow the groups of the step's frames at once, and what they cover is skipped.
    std::vector<WorkItem> items;
    for (const WorkItem& item : level)
      for (int s = item.s0; s < item.s1; ++s) items.push_back({item.pair, item.node_a, item.node_b, s, s + 1});
    std::sort(items.begin(), items.end(), [](const WorkItem& x, const WorkItem& y) {
      return std::tie(x.pair, x.s0, x.node_a, x.node_b) < std::tie(y.pair, y.s0, y.node_a, y.node_b);
    });
    std::vector<std::pair<std::size_t, std::size_t>> steps;  // runs of items of one step
    for (std::size_t i = 0; i < items.size(); ++i)
      if (i == 0 || items[i].pair != items[i - 1].pair || items[i].s0 != items[i - 1].s0) steps.push_back({i, i + 1});
      else steps.back().second = i + 1;
    const auto step_of = [&](std::size_t g) { return std::pair{items[steps[g].first].pair, items[steps[g].first].s0}; };
    // The even steps of every pair timeline first; an odd step waits for its even neighbors,
    // then starts from the triangle pairs that made their extents in the frames they share
    // (`neighbor_leaves`). Otherwise a step starts as soon as a thread is free: there is no
    // barrier between the rounds, and what a step finds depends on nothing else.
    std::map<std::pair<int, int>, std::size_t> index_of;
    for (std::size_t g = 0; g < steps.size(); ++g) index_of.emplace(step_of(g), g);
    std::vector<std::vector<std::size_t>> neighbors(steps.size());  // of an odd step: its even neighbors
    std::vector<std::vector<std::size_t>> unblocks(steps.size());   // of an even step: its odd neighbors
    for (std::size_t g = 0; g < steps.size(); ++g) {
      const auto [pair, s] = step_of(g);
      if (s % 2 == 0) continue;
      for (const int next : {s - 1, s + 1})
        if (const auto at = index_of.find({pair, next}); at != index_of.end()) {
          neighbors[g].push_back(at->second);
          unblocks[at->second].push_back(g);
        }
    }
    const auto waiting = std::make_unique<std::atomic<int>[]>(steps.size());
    std::vector<std::size_t> ready;  // the even steps, and the odd ones without even neighbors
    for (std::size_t g = 0; g < steps.size(); ++g) {
      waiting[g] = static_cast<int>(neighbors[g].size());
      if (neighbors[g].empty()) ready.push_back(g);
    }
    std::vector<std::vector<LineContact>> step_contacts(steps.size());
    std::vector<DetectionStats> step_stats(steps.size());
    // Progress and previews, one call at a time, every `kStepsPerReport` steps done.
    std::mutex reporting;
    std::size_t done = 0;
    std::vector<bool> finished(steps.size(), false);
    std::vector<std::pair<double, double>> found_ranges = contact_ranges();
    std::atomic<bool> cancelled = false;
    const auto report = [&](std::size_t g) {
      const std::lock_guard lock(reporting);
      if (cancelled) return;
      finished[g] = true;
      for (const LineContact& c : step_contacts[g]) found_ranges.push_back({c.contact.t0, c.contact.t1});
      if (++done % kStepsPerReport != 0 && done != steps.size()) return;
      if (callbacks.preview) {
        std::vector<std::pair<double, double>> ranges = found_ranges;
        for (std::size_t h = 0; h < steps.size(); ++h)
          if (!finished[h]) {
            const auto [pair, s] = step_of(h);
            ranges.push_back({tr.lines[pair].times[s], tr.lines[pair].times[s + 1]});
          }
        callbacks.preview({depth, union_of(std::move(ranges))});
      }
      if (!report_progress(callbacks.progress, 0.5 + 0.5 * static_cast<double>(done) / steps.size())) cancelled = true;
    };
    tbb::enumerable_thread_specific<UrgencyQueue<WorkItem>> queues;
    tbb::parallel_for_each(ready.begin(), ready.end(), [&](std::size_t g, tbb::feeder<std::size_t>& feeder) {
      if (cancelled) return;
      std::vector<LineContact>& local = step_contacts[g];
      const ItemContext context{step_groups, local, step_stats[g]};
      // Best first: the item whose reach sticks out of the groups found so far the most for
      // its size (children inherit their parent's protrusion), so that the contacts that
      // make the groups' extremes come early and prune the rest; first of all
      // the hinted leaf pairs, then the items where nothing is known yet, deepest first (to
      // find a first contact soon).
      BoundCache<family>& bounds = bound_caches.local();
      UrgencyQueue<WorkItem>& queue = queues.local();  // empty, its buckets' memory kept from earlier steps
      std::vector<WorkItem> children;
      const auto run = [&](const WorkItem& item) {  // its contacts join the step's groups at once
        const std::size_t known = local.size();
        const double urgency = process(tr, item, children, context, bounds);
        for (std::size_t c = known; c < local.size(); ++c) found.add(local[c].line, local[c].contact);
        return urgency;
      };
      const auto [pair, s] = step_of(g);
      std::vector<std::pair<int, int>> leaves;
      if (const auto at = hinted.find({pair, s}); at != hinted.end()) leaves = at->second;
      for (const std::size_t h : neighbors[g])
        for (const auto& leaf_pair : neighbor_leaves(tr, pair, s, step_contacts[h])) leaves.push_back(leaf_pair);
      tidy(leaves);
      for (const auto& [leaf_a, leaf_b] : leaves) run({pair, leaf_a, leaf_b, s, s + 1});
      for (std::size_t i = steps[g].second; i-- > steps[g].first;) queue.push(items[i], kUnknownUrgency);
      while (!queue.empty()) {
        const double urgency = run(queue.pop());
        for (auto child = children.rbegin(); child != children.rend(); ++child) queue.push(*child, urgency);
        children.clear();
      }
      for (const std::size_t odd : unblocks[g])
        if (--waiting[odd] == 0) feeder.add(odd);
      report(g);
    });
    if (cancelled) return false;
    for (const bool odd : {false, true})
      for (std::size_t g = 0; g < steps.size(); ++g)
        if ((step_of(g).second % 2 == 1) == odd) {
          for (const LineContact& c : step_contacts[g]) contacts.push_back(c.contact);
          stats += step_stats[g];
        }
  }
  std::sort(contacts.begin(), contacts.end(), contact_less);
  // A hinted leaf pair that the search reaches again reports the same contacts again.
  contacts.erase(std::unique(contacts.begin(), contacts.end(),
                             [](const TriangleContact& x, const TriangleContact& y) {
                               return !contact_less(x, y) && !contact_less(y, x) && x.possible == y.possible &&
                                      x.step_t0 == y.step_t0 && x.box.min() == y.box.min() && x.box.max() == y.box.max();
                             }),
                 contacts.end());
  return true;
}

}  // namespace

std::vector<TraversalRange> candidate_pairs(const BodyTrees& trees, const std::vector<PartProxy>& proxies,
                                            const scene::Reconfigurable& scene, const DetectorOptions& options) {
  const double pad = traversal_pad(scene, proxies);
  std::vector<TraversalRange> pairs;
  const auto run = [&]<DopFamily family>() {
    const int n = static_cast<int>(proxies.size());
    std::vector<Kdop<family>> sweeps;
    sweeps.reserve(n);
    for (int p = 0; p < n; ++p)  // as traverse_ranges bounds a range [0, 1]
      sweeps.push_back(sweep_bound<family>(proxies[p], *trees[p], 0.0, 1.0, pad,
                                           options.conservative ? proxies[p].deviation : 0.0));
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return sweeps[x].lo[0] < sweeps[y].lo[0]; });
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n && sweeps[order[j]].lo[0] <= sweeps[order[i]].hi[0]; ++j)
        if (sweeps[order[i]].overlaps(sweeps[order[j]]))
          pairs.push_back({std::min(order[i], order[j]), std::max(order[i], order[j]), 0.0, 1.0});
  };
  switch (options.dop) {
    case DopFamily::k8: run.template operator()<DopFamily::k8>(); break;
    case DopFamily::k28: run.template operator()<DopFamily::k28>(); break;
    case DopFamily::k80: run.template operator()<DopFamily::k80>(); break;
  }
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
  bool finished = false;
  const auto run = [&]<DopFamily family>() {
    // Pairs whose parts' whole sweeps over the range cannot meet are left out at once.
    std::map<std::tuple<int, double, double>, Kdop<family>> sweeps;
    const auto sweep = [&](int part, double t0, double t1) -> const Kdop<family>& {
      auto at = sweeps.find({part, t0, t1});
      if (at == sweeps.end()) {
        const double deviation = options.conservative ? proxies[part].deviation : 0.0;
        at = sweeps.emplace(std::tuple{part, t0, t1}, sweep_bound<family>(proxies[part], *trees[part], t0, t1, pad, deviation)).first;
      }
      return at->second;
    };
    std::vector<PairTimeline> lines;
    for (const TraversalRange& r : ranges) {
      ++stats.bound_tests;
      if (sweep(r.a, r.t0, r.t1).overlaps(sweep(r.b, r.t0, r.t1))) lines.push_back(make_timeline(proxies, r.a, r.b, r.t0, r.t1));
    }
    const Traversal<family> traversal(scene, trees, proxies, options, std::move(lines), pad);
    finished = run_traversal(traversal, hints, contacts, stats, callbacks);
  };
  switch (options.dop) {
    case DopFamily::k8: run.template operator()<DopFamily::k8>(); break;
    case DopFamily::k28: run.template operator()<DopFamily::k28>(); break;
    case DopFamily::k80: run.template operator()<DopFamily::k80>(); break;
  }
  return finished;
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

std::vector<ContactHint> extreme_contacts(const std::vector<TriangleContact>& contacts, const FrameGrid& grid) {
  // Per pair of parts and frame: the contact with the lowest box minimum and the highest box
  // maximum along each axis, the earliest start and the latest end.
  constexpr int kExtremes = 8;
  std::map<std::tuple<int, int, int>, std::array<const TriangleContact*, kExtremes>> extremes;
  for (const TriangleContact& c : contacts) {
    if (c.possible) continue;
    auto& best = extremes.try_emplace({c.part_a, c.part_b, frame_of_contact(grid, c)}).first->second;
    const auto keep = [&](int k, auto further) {
      if (!best[k] || further(*best[k])) best[k] = &c;
    };
    for (int axis = 0; axis < 3; ++axis) {
      keep(axis, [&](const TriangleContact& b) { return c.box.min()[axis] < b.box.min()[axis]; });
      keep(3 + axis, [&](const TriangleContact& b) { return c.box.max()[axis] > b.box.max()[axis]; });
    }
    keep(6, [&](const TriangleContact& b) { return c.t0 < b.t0; });
    keep(7, [&](const TriangleContact& b) { return c.t1 > b.t1; });
  }
  std::vector<ContactHint> hints;
  for (const auto& [key, best] : extremes)
    for (const TriangleContact* c : best)
      hints.push_back({c->part_a, c->triangle_a, c->part_b, c->triangle_b, (c->t0 + c->t1) / 2});
  return hints;
}

Eigen::MatrixX3d proxy_points(const PartProxy& proxy, const Eigen::MatrixX3d& rest, double t) {
  const Affine m = proxy_map(proxy, t);
  return (rest * m.L.transpose()).rowwise() + m.x.transpose();
}

Eigen::MatrixX3d proxy_vertices(const scene::Reconfigurable& scene, const PartProxy& proxy, int part, double t) {
  return proxy_points(proxy, scene.parts[part].mesh.V, t);
}


}  // namespace reconfig::collision::detail
