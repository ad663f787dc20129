#include "reconfig/resolve/penetration.h"

#include <gtest/gtest.h>

#include "geometry/mesh_test_helpers.h"
#include "reconfig/geometry/point_in_solid.h"
#include "placements.h"
#include "reconfig/geometry/primitives.h"

namespace reconfig::resolve {
namespace {

using testing::moved;
using testing::place;

/// Slow reference: each sample classified by winding numbers (its distance to the surface is
/// the signed distance's, itself tested against brute force in signed_distance_test).
double reference_depth(const PartShape& inner, const Eigen::Isometry3d& pi, const geometry::Mesh& outer_mesh,
                       const Eigen::Isometry3d& po) {
  double depth = 0;
  const geometry::MeshSignedDistance outer(outer_mesh);
  for (std::size_t s = 0; s < inner.sample_points.size(); ++s) {
    const Eigen::Vector3d q = po.inverse() * (pi * inner.sample_points[s]);
    if (geometry::point_in_solid(outer_mesh, q)) depth += inner.sample_weights[s] * std::abs(outer.query(q).distance);
  }
  return depth;
}

TEST(Penetration, ABoxWhollyInsideAnotherHasItsMeanDepth) {
  const geometry::Mesh big = geometry::make_box({2, 2, 2}), small = geometry::make_box({0.2, 0.2, 0.2});
  const PartShape b(big), s(small);
  const Penetration centered = penetration(s, place({0, 0, 0}), b, place({0, 0, 0}));
  EXPECT_NEAR(centered.depth, 0.9, 1e-12);  // every corner is 0.9 from the nearest face
  EXPECT_EQ(centered.samples_inside, 8);
  // Moved toward +x, its corners are 0.4 and 0.6 from the nearest face (x = 1).
  const Penetration off = penetration(s, place({0.5, 0, 0}), b, place({0, 0, 0}));
  EXPECT_GT(off.depth, 0.4);
  EXPECT_LT(off.depth, 0.6);
  EXPECT_LT(off.gradient.force.x(), 0);  // the depth falls as the small box moves on toward +x
}

TEST(Penetration, MatchesTheReferenceOnRandomPlacements) {
  testing::RandomPlacements random(8);
  const geometry::Mesh a = geometry::make_sphere(0.5, 2), b = geometry::make_box({1, 0.5, 0.7});
  const PartShape sa(a), sb(b);
  int inside = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d pa = random.near_origin(0.3);
    const Eigen::Isometry3d pb = random.near_origin(0);
    const Penetration p = penetration(sa, pa, sb, pb);
    const double reference = reference_depth(sa, pa, b, pb) + reference_depth(sb, pb, a, pa);
    EXPECT_NEAR(p.depth, reference, 1e-12) << trial;
    inside += p.samples_inside > 0;
  }
  EXPECT_GT(inside, 15);
}

TEST(Penetration, RaysSettleSamplesOutsideAClosedPartWithoutADistanceQuery) {
  // Two spheres overlapping in a lens: many of a's samples lie in b's box but outside b.
  testing::RandomPlacements random(10);
  const geometry::Mesh ma = geometry::make_sphere(0.5, 3), mb = geometry::make_sphere(0.45, 3);
  const PartShape a(ma), b(mb);
  int rays = 0, queries = 0, inside = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d pa = place(0.6 * random.vector().normalized(), random.rotation());
    const Eigen::Isometry3d pb = random.near_origin(0.02);
    const Penetration p = penetration(a, pa, b, pb);
    EXPECT_NEAR(p.depth, reference_depth(a, pa, mb, pb) + reference_depth(b, pb, ma, pa), 1e-12) << trial;
    rays += p.ray_tests;
    queries += p.distance_queries;
    inside += p.samples_inside;
  }
  EXPECT_GT(inside, 100);          // overlapping poses are exercised
  EXPECT_GT(rays, queries + 500);  // and most samples in the box are settled by a ray
}

TEST(Penetration, PartsOfOverlappingOrNestedShellsHaveTheirWindingNumbersDepth) {
  // One part made of two shells (as a merged file gives): a sphere holding a smaller one, and
  // a sphere overlapping a box. Where shells nest or overlap the winding number is 2, inside.
  const geometry::Mesh nested = geometry::testing::merge(geometry::make_sphere(0.5, 3), geometry::make_sphere(0.25, 2));
  geometry::Mesh box = geometry::make_box({0.6, 0.6, 0.6});
  box.V.rowwise() += Eigen::RowVector3d(0.3, 0.1, 0);
  const geometry::Mesh overlapping = geometry::testing::merge(geometry::make_sphere(0.5, 3), box);
  const geometry::Mesh small = geometry::make_box({0.1, 0.1, 0.1});
  const PartShape s(small);
  for (const geometry::Mesh& outer : {nested, overlapping}) {
    const PartShape o(outer);
    ASSERT_TRUE(o.oriented);
    const Penetration p = penetration(s, place({0.12, 0.04, 0.02}), o, place({0, 0, 0}));
    EXPECT_EQ(p.samples_inside, 8);  // every corner of the small box, inside both shells
    EXPECT_NEAR(p.depth, reference_depth(s, place({0.12, 0.04, 0.02}), outer, place({0, 0, 0})), 1e-12);
  }
}

TEST(Penetration, OpenOrInconsistentlyOrientedPartsAreQueriedWithoutRays) {
  // A ray's count means nothing there: one face missing, or one face turned.
  geometry::Mesh open = geometry::make_box({1, 1, 1});
  open.F.conservativeResize(open.F.rows() - 1, 3);
  geometry::Mesh turned = geometry::make_box({1, 1, 1});
  turned.F.row(0) = Eigen::RowVector3i(turned.F(0, 0), turned.F(0, 2), turned.F(0, 1));
  for (const geometry::Mesh& mesh : {open, turned}) {
    const PartShape part(mesh);
    ASSERT_FALSE(part.oriented);
    const Penetration p = penetration(part, place({0.3, 0.1, 0.2}), part, place({0, 0, 0}));
    EXPECT_EQ(p.ray_tests, 0);
    EXPECT_GT(p.distance_queries, 0);
    EXPECT_GT(p.samples_inside, 0);
  }
  EXPECT_FALSE(PartShape(open).closed);
  EXPECT_TRUE(PartShape(turned).closed);
}

TEST(Penetration, GradientMatchesFiniteDifferences) {
  testing::RandomPlacements random(9);
  const PartShape a(geometry::make_sphere(0.5, 2)), b(geometry::make_box({1, 0.5, 0.7}));
  int checked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Isometry3d pa = random.near_origin(0.25);
    const Eigen::Isometry3d pb = random.near_origin(0);
    const Penetration p = penetration(a, pa, b, pb);
    if (p.samples_inside == 0) continue;
    const Eigen::Vector3d v = random.vector(), w = random.vector();
    const double h = 1e-7;
    const double fd = (penetration(a, moved(pa, v, w, h), b, pb).depth - penetration(a, moved(pa, v, w, -h), b, pb).depth) /
                      (2 * h);
    EXPECT_NEAR(p.gradient.force.dot(v) + p.gradient.torque.dot(w), fd, 1e-5 * (1 + std::abs(fd))) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(Penetration, LiftingAFaceOnOverlapLowersIt) {
  // Two boxes overlapping face-on: the contour's length does not change as the upper one
  // rises, the penetration does.
  const PartShape lower(geometry::make_box({2, 2, 1})), upper(geometry::make_box({1, 1, 1}));
  const Penetration deep = penetration(upper, place({0, 0, 0.8}), lower, place({0, 0, 0}));
  const Penetration shallow = penetration(upper, place({0, 0, 0.9}), lower, place({0, 0, 0}));
  EXPECT_GT(deep.depth, shallow.depth);
  EXPECT_GT(shallow.depth, 0);
  EXPECT_LT(deep.gradient.force.z(), 0);  // rising lowers it
}

}  // namespace
}  // namespace reconfig::resolve
