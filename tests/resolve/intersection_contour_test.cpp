#include "reconfig/resolve/intersection_contour.h"

#include <gtest/gtest.h>

#include <numbers>

#include "placements.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/geometry/triangle_intersection.h"

namespace reconfig::resolve {
namespace {

using testing::moved;
using testing::place;

/// Slow reference: the intersection segments of every pair of triangles, no tree.
double brute_force_length(const geometry::Mesh& a, const Eigen::Isometry3d& pa, const geometry::Mesh& b,
                          const Eigen::Isometry3d& pb) {
  double length = 0;
  const auto corner = [](const geometry::Mesh& m, const Eigen::Isometry3d& p, int f, int k) {
    return Eigen::Vector3d(p * Eigen::Vector3d(m.V.row(m.F(f, k))));
  };
  for (int f = 0; f < a.face_count(); ++f)
    for (int g = 0; g < b.face_count(); ++g) {
      const auto c = geometry::intersect_triangles(corner(a, pa, f, 0), corner(a, pa, f, 1), corner(a, pa, f, 2),
                                                   corner(b, pb, g, 0), corner(b, pb, g, 1), corner(b, pb, g, 2));
      if (c.intersect && !c.coplanar && c.points.size() == 2) length += (c.points[1] - c.points[0]).norm();
    }
  return length;
}

TEST(IntersectionContour, SphereCutByABoxFaceIsACircle) {
  const geometry::Mesh sphere = geometry::make_sphere(1.0, 4);
  const PartShape s(sphere), box(geometry::make_box({4, 4, 4}));
  const double top = 0.3;  // the box's top face cuts the sphere at z = 0.3
  const IntersectionContour contour = intersection_contour(s, place({0, 0, 0}), box, place({0, 0, top - 2}));
  const double radius = std::sqrt(1 - top * top);
  // The mesh's vertices lie on the sphere, so its section lies inside the circle, within the
  // discretization (edges of about 0.05 at 4 subdivisions sag by < 0.1 %).
  EXPECT_LE(contour.length, 2 * std::numbers::pi * radius);
  EXPECT_GE(contour.length, 0.99 * 2 * std::numbers::pi * radius);
  ASSERT_EQ(contour.polylines.size(), 1u);
  EXPECT_TRUE(contour.polylines[0].closed);
  for (const Eigen::Vector3d& p : contour.polylines[0].points) EXPECT_NEAR(p.z(), top, 1e-12);
}

TEST(IntersectionContour, TwoBoxesCrossingGiveTheirExactSquares) {
  const PartShape big(geometry::make_box({2, 2, 2})), post(geometry::make_box({1, 1, 4}));
  for (double angle : {0.0, 0.5, 1.1}) {
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
    const IntersectionContour contour = intersection_contour(big, place({0, 0, 0}), post, place({0.1, 0.05, 0}, turn));
    // The post pierces the top and bottom faces: two unit squares.
    EXPECT_NEAR(contour.length, 8.0, 1e-12) << angle;
    ASSERT_EQ(contour.polylines.size(), 2u) << angle;
    for (const ContourPolyline& line : contour.polylines) EXPECT_TRUE(line.closed);
  }
}

TEST(IntersectionContour, MatchesAllTrianglePairsOnRandomPlacements) {
  testing::RandomPlacements random(3);
  const std::vector<geometry::Mesh> meshes = {geometry::make_sphere(0.6, 2), geometry::make_box({1, 0.6, 0.3}),
                                              geometry::make_cylinder(0.3, 1.0, 12)};
  int crossing = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const geometry::Mesh& a = meshes[trial % 3];
    const geometry::Mesh& b = meshes[(trial / 3) % 3];
    const Eigen::Isometry3d pa = random.near_origin(0.3);
    const Eigen::Isometry3d pb = random.near_origin(0.3);
    const IntersectionContour contour = intersection_contour(PartShape(a), pa, PartShape(b), pb);
    const double reference = brute_force_length(a, pa, b, pb);
    EXPECT_NEAR(contour.length, reference, 1e-9 * (1 + reference)) << trial;
    if (reference > 0) {
      ++crossing;
      // Closed meshes in general position cross in closed loops.
      for (const ContourPolyline& line : contour.polylines) EXPECT_TRUE(line.closed) << trial;
    }
  }
  EXPECT_GT(crossing, 30);  // most placements do cross
}

/// A corner a hair inside or outside a face, where the contour's floating-point plane test
/// cannot be sure and must leave the pairs to the exact test: the same segments as all
/// triangle pairs tested exactly.
TEST(IntersectionContour, ACornerAHairFromAFaceMatchesAllTrianglePairs) {
  const geometry::Mesh box = geometry::make_box({1, 1, 1}), ball = geometry::make_sphere(0.5, 2);
  const PartShape box_shape(box), ball_shape(ball);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 1, 0.2).normalized()));
  // The ball's corner nearest the box, turned, is put `gap` beyond the box's face x = 0.5.
  const Eigen::MatrixX3d turned = ball.V * turn.toRotationMatrix().transpose();
  Eigen::Index lowest = 0;
  turned.col(0).minCoeff(&lowest);
  int crossing = 0, cases = 0;
  for (double gap : {-1e-6, -1e-9, -1e-12, -1e-14, 0.0, 1e-14, 1e-12, 1e-9}) {
    const Eigen::Vector3d at(0.5 + gap - turned(lowest, 0), 0.0123 - turned(lowest, 1), 0.0311 - turned(lowest, 2));
    const Eigen::Isometry3d pa = place({0, 0, 0}), pb = place(at, turn);
    const IntersectionContour contour = intersection_contour(box_shape, pa, ball_shape, pb);
    int reference = 0;  // segments of all triangle pairs
    for (int f = 0; f < box.face_count(); ++f)
      for (int g = 0; g < ball.face_count(); ++g) {
        const auto corner = [](const geometry::Mesh& m, const Eigen::Isometry3d& p, int h, int k) {
          return Eigen::Vector3d(p * Eigen::Vector3d(m.V.row(m.F(h, k))));
        };
        const auto c = geometry::intersect_triangles(corner(box, pa, f, 0), corner(box, pa, f, 1), corner(box, pa, f, 2),
                                                     corner(ball, pb, g, 0), corner(ball, pb, g, 1), corner(ball, pb, g, 2));
        reference += c.intersect && !c.coplanar && c.points.size() == 2;
      }
    EXPECT_EQ(static_cast<int>(contour.segments.size()), reference) << "gap " << gap;
    crossing += reference > 0;
    ++cases;
  }
  EXPECT_GE(crossing, 3);     // the corners inside cross ...
  EXPECT_LT(crossing, cases);  // ... and those outside do not
}

TEST(IntersectionContour, DegenerateContactsGiveFiniteAnswers) {
  const PartShape box(geometry::make_box({1, 1, 1}));
  // Faces touching face to face (coplanar): no curve.
  EXPECT_EQ(intersection_contour(box, place({0, 0, 0}), box, place({1, 0, 0})).length, 0.0);
  // The same box twice: every face coplanar with one of the other.
  const IntersectionContour same = intersection_contour(box, place({0, 0, 0}), box, place({0, 0, 0}));
  EXPECT_TRUE(std::isfinite(same.length));
  // A corner exactly on a face, and edges through edges.
  const Eigen::Quaterniond tilt = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(1, 1, 1).normalized(), Eigen::Vector3d::UnitZ());
  const IntersectionContour corner =
      intersection_contour(box, place({0, 0, 0}), box, place({0, 0, 0.5 + std::sqrt(3.0) / 2}, tilt));
  EXPECT_TRUE(std::isfinite(corner.length));
  const TwistGradient g = contour_length_gradient(corner);
  EXPECT_TRUE(g.force.allFinite() && g.torque.allFinite());
  const IntersectionContour edges = intersection_contour(box, place({0, 0, 0}), box, place({0.5, 0.5, 0}));
  EXPECT_TRUE(std::isfinite(edges.length));
}

TEST(IntersectionContour, EdgesLyingInTheOtherSurfaceCountOnceWhereTheSurfaceCrosses) {
  // A unit box turned 45° about x, its center on the big box's top face: its two side edges
  // lie in that face, with one of their faces above it and one below (the surface crosses
  // along them), and its end faces cross along their diagonals: 2·1 + 2·√2.
  const PartShape big(geometry::make_box({2, 2, 2})), cube(geometry::make_box({1, 1, 1}));
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(std::numbers::pi / 4, Eigen::Vector3d::UnitX()));
  const IntersectionContour crossing = intersection_contour(big, place({0, 0, 0}), cube, place({0, 0, 1}, turn));
  EXPECT_NEAR(crossing.length, 2 + 2 * std::sqrt(2.0), 1e-9);
  // Resting on the face along its bottom edge (both faces of the edge above): touching only.
  const IntersectionContour resting =
      intersection_contour(big, place({0, 0, 0}), cube, place({0, 0, 1 + std::sqrt(0.5)}, turn));
  EXPECT_NEAR(resting.length, 0, 1e-9);
}

TEST(IntersectionContour, LengthGradientMatchesFiniteDifferences) {
  testing::RandomPlacements random(5);
  const PartShape sphere(geometry::make_sphere(0.6, 3)), box(geometry::make_box({1, 0.7, 0.4}));
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Isometry3d pa = random.near_origin(0.3);
    const Eigen::Isometry3d pb = random.near_origin(0);
    const IntersectionContour contour = intersection_contour(sphere, pa, box, pb);
    if (contour.length == 0) continue;
    const TwistGradient g = contour_length_gradient(contour);
    const Eigen::Vector3d v = random.vector(), w = random.vector();
    const double h = 1e-8;  // small enough to stay clear of the kinks (a vertex crossing a face) nearby
    const double fd = (intersection_contour(sphere, moved(pa, v, w, h), box, pb).length -
                       intersection_contour(sphere, moved(pa, v, w, -h), box, pb).length) /
                      (2 * h);
    EXPECT_NEAR(g.force.dot(v) + g.torque.dot(w), fd, 1e-4 * (1 + std::abs(fd))) << trial;
    // Moving b the other way is the same relative motion.
    const double fd_b = (intersection_contour(sphere, pa, box, moved(pb, v, w, h)).length -
                         intersection_contour(sphere, pa, box, moved(pb, v, w, -h)).length) /
                        (2 * h);
    EXPECT_NEAR(-(g.force.dot(v) + g.torque.dot(w)), fd_b, 1e-4 * (1 + std::abs(fd_b))) << trial;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

}  // namespace
}  // namespace reconfig::resolve
