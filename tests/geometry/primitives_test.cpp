#include "reconfig/geometry/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"

namespace reconfig::geometry {
namespace {

void expect_valid_solid(const Mesh& mesh) {
  const MeshReport report = check_mesh(mesh);
  EXPECT_TRUE(report.is_valid_solid()) << report.summary();
  EXPECT_TRUE(report.self_intersections_checked);
  EXPECT_EQ(report.component_count, 1);
  EXPECT_FALSE(report.unreferenced_vertices.any());
}

TEST(MakeBox, IsAValidSolidWithTheRightVolumeAndBounds) {
  const Mesh box = make_box({1, 2, 3});
  EXPECT_EQ(box.vertex_count(), 8);
  EXPECT_EQ(box.face_count(), 12);
  expect_valid_solid(box);
  const MassProperties mp = mass_properties(box);
  EXPECT_DOUBLE_EQ(mp.volume, 6);
  EXPECT_DOUBLE_EQ(mp.surface_area, 2 * (2 + 3 + 6));
  EXPECT_LT(mp.center_of_mass.norm(), 1e-15);
  EXPECT_TRUE(mp.bounds.min().isApprox(Eigen::Vector3d(-0.5, -1, -1.5)));
  EXPECT_TRUE(mp.bounds.max().isApprox(Eigen::Vector3d(0.5, 1, 1.5)));
}

TEST(MakeCylinder, IsAValidSolidWhoseVolumeIsThePrismOverTheInscribedPolygon) {
  for (int segments : {3, 4, 7, 48, 200}) {
    SCOPED_TRACE(segments);
    const double r = 0.7, h = 2.5;
    const Mesh cylinder = make_cylinder(r, h, segments);
    EXPECT_EQ(cylinder.vertex_count(), 2 * segments + 2);
    EXPECT_EQ(cylinder.face_count(), 4 * segments);
    expect_valid_solid(cylinder);
    const MassProperties mp = mass_properties(cylinder);
    const double polygon = segments / 2.0 * r * r * std::sin(2 * std::numbers::pi / segments);
    EXPECT_NEAR(mp.volume, polygon * h, 1e-12);
    EXPECT_LT(mp.volume, std::numbers::pi * r * r * h);  // inscribed: strictly less than the cylinder
    EXPECT_LT(mp.center_of_mass.norm(), 1e-12);
    EXPECT_NEAR(mp.bounds.min().z(), -h / 2, 1e-15);
    EXPECT_NEAR(mp.bounds.max().z(), h / 2, 1e-15);
  }
}

TEST(MakeSphere, IsAValidSolidBetweenItsInscribedAndCircumscribedBalls) {
  for (int s = 0; s <= 4; ++s) {
    SCOPED_TRACE(s);
    const double r = 1.3;
    const Mesh sphere = make_sphere(r, s);
    const int expected_faces = 20 * (1 << (2 * s));
    EXPECT_EQ(sphere.face_count(), expected_faces);
    EXPECT_EQ(sphere.vertex_count(), expected_faces / 2 + 2);
    for (int v = 0; v < sphere.vertex_count(); ++v) EXPECT_NEAR(sphere.V.row(v).norm(), r, 1e-12);
    expect_valid_solid(sphere);
    // The polytope lies between the ball of its nearest face plane and the circumscribed ball.
    double inradius = r;
    for (int f = 0; f < sphere.face_count(); ++f) {
      const Eigen::Vector3d a = sphere.V.row(sphere.F(f, 0)), b = sphere.V.row(sphere.F(f, 1)),
                            c = sphere.V.row(sphere.F(f, 2));
      const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
      EXPECT_GT(n.dot(a), 0) << "face " << f << " points inward";
      inradius = std::min(inradius, n.dot(a));
    }
    const MassProperties mp = mass_properties(sphere);
    const double ball = 4.0 / 3 * std::numbers::pi;
    EXPECT_LT(mp.volume, ball * r * r * r);
    EXPECT_GT(mp.volume, ball * inradius * inradius * inradius);
    EXPECT_LT(mp.center_of_mass.norm(), 1e-12);
  }
  // Convergence: subdivision 5 is within 0.2 % of the ball.
  const double v5 = mass_properties(make_sphere(1, 5)).volume;
  EXPECT_NEAR(v5, 4.0 / 3 * std::numbers::pi, 0.002 * 4.0 / 3 * std::numbers::pi);
}

}  // namespace
}  // namespace reconfig::geometry
