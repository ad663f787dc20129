#pragma once
/// @file
/// A part's placement at one proxy sample, and the extents of its tree's nodes along the axes
/// of a k-DOP family there: from each node's box, tightened by its diagonal slack
/// (`BodyTree::diagonal_slack`).

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "reconfig/collision/body_tree.h"
#include "reconfig/collision/kdop.h"

namespace reconfig::collision::detail {

/// A proxy's placement at one time: between two samples the vertices interpolate linearly,
/// which is an affine (not rigid) map.
struct Affine {
  Eigen::Matrix3d L = Eigen::Matrix3d::Identity();
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& v) const { return L * v + x; }
  bool operator==(const Affine& o) const { return L == o.L && x == o.x; }
};

/// The diagonal of space (`BodyTree::DiagonalSlack`) with signs d ∈ {−1, 0, 1}³, by the code
/// (d₀ + 1) + 3(d₁ + 1) + 9(d₂ + 1): its index i, or −i − 1 for −d.
inline constexpr std::array<int, 27> kDiagonalIndex = [] {
  std::array<int, 27> index{};
  constexpr auto kSigns = dop_axis_signs<DopFamily::k28>();
  for (int i = 0; i < 10; ++i) {
    const auto& d = kSigns[3 + i];
    index[(d[0] + 1) + 3 * (d[1] + 1) + 9 * (d[2] + 1)] = i;
    index[(1 - d[0]) + 3 * (1 - d[1]) + 9 * (1 - d[2])] = -i - 1;
  }
  return index;
}();

/// A part's placement at one sample, with what bounding along a family's axes needs: a rest
/// point's axis values are those of its placed point (`axis_values`, additions only), and a
/// rest-frame box's half extents along axis j are reach_j · half, where reach_j = |Lᵀ ds_j|
/// (entrywise; ds_j the spatial part of axis j). The extents are those of exact arithmetic:
/// callers pad them against rounding.
template <DopFamily family>
struct SampleAxes {
  static constexpr int K = Kdop<family>::kAxes;
  using Axes = Eigen::Matrix<double, K, 1>;
  Affine map;
  double t = 0;
  Eigen::Matrix<double, K, 3> reach;

  /// The axes at placement `m`, at time `time`; with `tighten`, also what `node_extents` needs.
  SampleAxes(const Affine& m, double time, bool tighten) : map(m), t(time) {
    if (tighten) tightenings.reserve(4 * K);
    const auto& dirs = dop_axes<family>();
    for (int j = 0; j < K; ++j) {
      const Eigen::Vector3d w = m.L.transpose() * dirs[j].template head<3>();
      reach.row(j) = w.cwiseAbs().transpose();
      if (!tighten) continue;
      // The diagonals d of w's signs over two or three of its coordinates, λ the smallest |w_k| there.
      const auto size = reach.row(j);
      const auto add = [&](int k0, int k1, int k2) {  // k2 < 0 for two coordinates
        std::array<int, 3> d{};
        for (const int k : {k0, k1, k2})
          if (k >= 0) d[k] = w[k] > 0 ? 1 : -1;
        const double lambda = std::min(size[k0], k2 < 0 ? size[k1] : std::min(size[k1], size[k2]));
        if (!(lambda > 0)) return;
        const int i = kDiagonalIndex[(d[0] + 1) + 3 * (d[1] + 1) + 9 * (d[2] + 1)];
        const int up = i >= 0 ? i : 10 - i - 1, down = i >= 0 ? 10 + i : -i - 1;
        tightenings.push_back({static_cast<std::uint8_t>(j), static_cast<std::uint8_t>(up), static_cast<std::uint8_t>(down), lambda});
      };
      add(0, 1, -1);
      add(0, 2, -1);
      add(1, 2, -1);
      add(0, 1, 2);
    }
  }

  /// The axes at placement `m`, at time `time`, where `m` has the same linear part as `other`'s.
  SampleAxes(const SampleAxes& other, const Affine& m, double time) : SampleAxes(other) {
    map = m;
    t = time;
  }

  /// The values of a placed rest point along every axis.
  Axes point_values(const Eigen::Vector3d& rest) const { return axis_values<family>(map(rest), t); }

  /// Along axis j, w = Lᵀ(its spatial part) is λd + r for a diagonal d of space (of either
  /// sign) and a remainder r of w's signs, where λ ≥ 0 is the smallest |w_k| over d's nonzero
  /// coordinates: the box's bound along w then tightens by λ times the box's slack along d
  /// (`node_extents`). Up to four per axis (d over two or three coordinates).
  struct Tightening {
    std::uint8_t axis, up, down;  ///< up, down: indices into `BodyTree::DiagonalSlack`, along d and −d
    double lambda;
  };
  std::vector<Tightening> tightenings;  ///< none without `tighten`

  /// The extents [lo, hi] of a rest-frame box (center, half extents) along every axis.
  std::pair<Axes, Axes> box_extents(const Eigen::Vector3d& center, const Eigen::Vector3d& half) const {
    const Axes middle = point_values(center), spread = reach * half;
    return {middle - spread, middle + spread};
  }

  /// The extents [lo, hi] of a node along every axis: those of its box, tightened by its
  /// rest-frame 26-DOP. Along w = λd + r, the support of the node is at most λ·(its extent along
  /// d) + (the box's along r), which is the box's along w less λ·(its slack along d).
  std::pair<Axes, Axes> node_extents(const BodyTree::Node& node, const BodyTree::DiagonalSlack& slack) const {
    const auto [box_lo, box_hi] = box_extents(node.center, node.half);
    Axes lo = box_lo, hi = box_hi;
    for (const auto& [j, up, down, lambda] : tightenings) {
      hi[j] = std::min(hi[j], box_hi[j] - lambda * slack[up]);
      lo[j] = std::max(lo[j], box_lo[j] + lambda * slack[down]);
    }
    return {lo, hi};
  }
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

}  // namespace reconfig::collision::detail
