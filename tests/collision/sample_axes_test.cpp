// The extents of a part's tree nodes along a k-DOP family's axes at one placement: the nodes'
// boxes tightened by their diagonal slack, against the placed vertices themselves.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "collision/detail/sample_axes.h"
#include "reconfig/collision/body_tree.h"
#include "support/random_soup.h"

namespace reconfig::collision {
namespace {

/// A soup of `count` random triangles in [−1, 1]³, of sizes from slivers to a third of the box.
geometry::Mesh random_soup(std::mt19937& rng, int count) {
  return testing::random_soup(rng, count, {.lo = -1, .hi = 1, .min_size = 0.01, .max_size = 0.3});
}

/// The triangles under a node.
std::vector<int> triangles_under(const BodyTree& tree, int node) {
  std::vector<int> out, stack = {node};
  while (!stack.empty()) {
    const BodyTree::Node& n = tree.node(stack.back());
    stack.pop_back();
    if (n.leaf()) out.push_back(n.triangle);
    else stack.insert(stack.end(), {n.left, n.right});
  }
  return out;
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
}

TEST(BodyTree, DiagonalSlackIsHowFarTheBoxReachesBeyondTheTriangles) {
  std::mt19937 rng(11);
  const geometry::Mesh mesh = random_soup(rng, 300);
  const BodyTree tree(mesh);
  constexpr auto kSigns = dop_axis_signs<DopFamily::k28>();
  for (int i = 0; i < static_cast<int>(tree.nodes().size()); ++i) {
    const BodyTree::Node& node = tree.node(i);
    const BodyTree::DiagonalSlack& slack = tree.diagonal_slack(i);
    for (int j = 0; j < 10; ++j) {
      const Eigen::Vector3d d(kSigns[3 + j][0], kSigns[3 + j][1], kSigns[3 + j][2]);
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const int f : triangles_under(tree, i))
        for (int c = 0; c < 3; ++c) {
          const double value = d.dot(mesh.V.row(mesh.F(f, c)).transpose());
          lo = std::min(lo, value), hi = std::max(hi, value);
        }
      const double box_hi = d.dot(node.center) + d.cwiseAbs().dot(node.half);
      const double box_lo = d.dot(node.center) - d.cwiseAbs().dot(node.half);
      // Never more than the true slack (a bound from it stays conservative), and within float
      // rounding of it.
      EXPECT_GE(slack[j], 0);
      EXPECT_LE(slack[j], box_hi - hi + 1e-12) << "node " << i << ", diagonal " << j;
      EXPECT_GE(slack[j], box_hi - hi - 1e-6) << "node " << i << ", diagonal " << j;
      EXPECT_LE(slack[10 + j], lo - box_lo + 1e-12) << "node " << i << ", diagonal −" << j;
      EXPECT_GE(slack[10 + j], lo - box_lo - 1e-6) << "node " << i << ", diagonal −" << j;
    }
  }
}

/// Every placed vertex of every node lies within the node's extents along every axis, and the
/// extents lie within those of the node's box; returns the total width of the extents and that
/// of the boxes' over all nodes and axes.
template <DopFamily family>
std::pair<double, double> check_extents(const geometry::Mesh& mesh, const BodyTree& tree, const detail::Affine& map) {
  const detail::SampleAxes<family> axes(map, 0.25, true);
  constexpr double kRounding = 1e-12;
  double width = 0, box_width = 0;
  for (int i = 0; i < static_cast<int>(tree.nodes().size()); ++i) {
    const BodyTree::Node& node = tree.node(i);
    const auto [lo, hi] = axes.node_extents(node, tree.diagonal_slack(i));
    const auto [box_lo, box_hi] = axes.box_extents(node.center, node.half);
    for (const int f : triangles_under(tree, i))
      for (int c = 0; c < 3; ++c) {
        const auto values = axes.point_values(mesh.V.row(mesh.F(f, c)).transpose());
        for (int j = 0; j < axes.K; ++j) {
          EXPECT_GE(values[j], lo[j] - kRounding) << "node " << i << ", axis " << j;
          EXPECT_LE(values[j], hi[j] + kRounding) << "node " << i << ", axis " << j;
        }
      }
    for (int j = 0; j < axes.K; ++j) {
      EXPECT_GE(lo[j], box_lo[j]);
      EXPECT_LE(hi[j], box_hi[j]);
    }
    width += (hi - lo).sum();
    box_width += (box_hi - box_lo).sum();
  }
  return {width, box_width};
}

template <DopFamily family>
void check_random_placements(std::uint32_t seed) {
  std::mt19937 rng(seed);
  const geometry::Mesh mesh = random_soup(rng, 120);
  const BodyTree tree(mesh);
  std::uniform_real_distribution<double> unit(-1, 1), fraction(0, 1);
  double width = 0, box_width = 0;
  for (int trial = 0; trial < 12; ++trial) {
    // Rotations, and the affine maps between two of them that proxies interpolate through.
    const Eigen::Matrix3d r0 = random_rotation(rng), r1 = random_rotation(rng);
    const double s = trial % 3 == 0 ? 0.0 : fraction(rng);
    const detail::Affine map{(1 - s) * r0 + s * r1, Eigen::Vector3d(unit(rng), unit(rng), unit(rng))};
    const auto [w, b] = check_extents<family>(mesh, tree, map);
    width += w;
    box_width += b;
  }
  if (family != DopFamily::k8) {  // the 4D box has no diagonal axes to tighten
    EXPECT_LT(width, 0.9 * box_width) << "the slack should tighten rotated nodes' diagonal extents";
  }
}

TEST(SampleAxes, NodeExtentsHoldEveryPlacedVertex) {
  check_random_placements<DopFamily::k8>(1);
  check_random_placements<DopFamily::k28>(2);
  check_random_placements<DopFamily::k80>(3);
}

TEST(SampleAxes, NodeExtentsAreExactWhenTheMapPermutesTheAxes) {
  // Without rotation, or turned a quarter about z, every axis of the family maps to an axis or a
  // diagonal of the rest frame: the extents are the vertices' own, up to the slack's rounding.
  std::mt19937 rng(5);
  const geometry::Mesh mesh = random_soup(rng, 80);
  const BodyTree tree(mesh);
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix().array().round();
  for (const Eigen::Matrix3d& L : {Eigen::Matrix3d::Identity().eval(), quarter}) {
    const detail::SampleAxes<DopFamily::k28> axes({L, Eigen::Vector3d(0.5, -0.25, 2)}, 0.5, true);
    for (int i = 0; i < static_cast<int>(tree.nodes().size()); ++i) {
      const auto [lo, hi] = axes.node_extents(tree.node(i), tree.diagonal_slack(i));
      auto exact_lo = lo, exact_hi = hi;
      exact_lo.setConstant(HUGE_VAL);
      exact_hi.setConstant(-HUGE_VAL);
      for (const int f : triangles_under(tree, i))
        for (int c = 0; c < 3; ++c) {
          const auto values = axes.point_values(mesh.V.row(mesh.F(f, c)).transpose());
          exact_lo = exact_lo.cwiseMin(values);
          exact_hi = exact_hi.cwiseMax(values);
        }
      for (int j = 0; j < axes.K; ++j) {
        EXPECT_NEAR(lo[j], exact_lo[j], 1e-6) << "node " << i << ", axis " << j;
        EXPECT_NEAR(hi[j], exact_hi[j], 1e-6) << "node " << i << ", axis " << j;
      }
    }
  }
}

}  // namespace
}  // namespace reconfig::collision
