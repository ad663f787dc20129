#pragma once
/// @file
/// What every thread of the traversal reads: the pair timelines, each side's k-DOP axes at
/// every sample, the padding and tolerances, and the bounds of tree nodes over sample ranges
/// built from them (spacetime k-DOPs, spatial boxes between two times, triangle corners).

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "collision/detail/moving_bounds.h"
#include "collision/detail/pair_timeline.h"
#include "collision/detail/sample_axes.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/frame_grid.h"
#include "reconfig/collision/spacetime_detector.h"

namespace reconfig::collision::detail {

/// The smaller of two parts' sizes (their box diagonals): the scale of a pair's grouping gap,
/// box grid and urgency.
inline double smaller_diagonal(const BodyTree& a, const BodyTree& b) {
  const auto diagonal = [](const BodyTree& tree) { return 2 * tree.node(BodyTree::kRoot).half.norm(); };
  return std::min(diagonal(a), diagonal(b));
}

/// How far apart two contacts of a pair of parts in one frame may lie and still be grouped.
inline double group_gap(const DetectorOptions& options, double smaller_size) { return options.group_gap * smaller_size; }

inline Eigen::AlignedBox3d inflated(Eigen::AlignedBox3d box, double by) {
  box.min().array() -= by;
  box.max().array() += by;
  return box;
}

/// How far a part's bounds grow beyond the padding: its proxy's deviation in conservative mode,
/// plus half the distance a clearance traversal looks for (`DetectorOptions::closer_than`), so
/// that two parts' bounds meet wherever they may come that close.
inline double bound_growth(const DetectorOptions& options, const PartProxy& proxy) {
  return (options.conservative ? proxy.deviation : 0.0) + options.closer_than / 2;
}

/// Parts of fewer triangles are bounded by their nodes' boxes alone: their trees are shallow,
/// so tighter bounds prune little below them, and cost more than they save (on the kitchen,
/// whose parts have at most 380 triangles, 25 % more instructions for 8–12 % fewer bound tests;
/// on the 650-triangle eights, 28 % fewer instructions).
inline constexpr int kTightenedTriangles = 512;

/// Everything the traversal reads, shared by all threads.
template <DopFamily family>
struct TraversalInputs {
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

  TraversalInputs(const scene::Reconfigurable& s, const BodyTrees& t, const std::vector<PartProxy>& p,
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
  /// How far a side's bounds grow (`bound_growth`).
  double growth(int pair, int side) const { return bound_growth(options, proxies[side == 0 ? lines[pair].a : lines[pair].b]); }

  /// The node's spacetime k-DOP over samples [s0, s1], padded against rounding (and grown by
  /// `growth`); `ends`, if given, receives its k-DOPs at
  /// samples s0 and s1, padded (and grown) alike.
  Dop node_bound(int pair, int side, int node_index, int s0, int s1, std::array<Dop, 2>* ends = nullptr) const {
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
    const double grow = growth(pair, side);
    if (grow > 0) {
      dop.inflate(grow);
      if (ends)
        for (Dop& end : *ends) end.inflate(grow);
    }
    return dop;
  }

  /// The spatial box of a node over the time range [t0, t1] of the pair's timeline, padded
  /// like `node_bound` (and grown by `grow`): that of its placements at t0, t1 and the samples
  /// between, as it moves linearly in between.
  Eigen::AlignedBox3d node_box_between(int pair, int side, int node_index, double t0, double t1, double grow) const {
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
      return interpolate(line.maps[side][s], line.maps[side][s + 1], mu);
    };
    extend(at(t0));
    extend(at(t1));
    for (std::size_t k = 0; k < line.times.size(); ++k)
      if (line.times[k] > t0 && line.times[k] < t1) extend(line.maps[side][k]);
    return inflated(box, pad + grow);
  }

  double gap(int pair) const { return group_gap(options, size[pair]); }
  /// The cell of the grid a pair's contact boxes are rounded out to.
  double cell(int pair) const { return options.box_resolution * size[pair]; }

  /// A triangle's corners at sample s of the pair's timeline.
  MovingTriangle triangle_at(int pair, int side, int triangle, int s) const {
    const geometry::Mesh& m = mesh(pair, side);
    const Affine& map = lines[pair].maps[side][s];
    return {map(m.V.row(m.F(triangle, 0))), map(m.V.row(m.F(triangle, 1))), map(m.V.row(m.F(triangle, 2)))};
  }
};

}  // namespace reconfig::collision::detail
