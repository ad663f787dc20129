#include "reconfig/geometry/mass_properties.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "reconfig/common/input_error.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/primitives.h"
#include "mesh_test_helpers.h"
#include "support/test_data.h"

namespace reconfig::geometry {
namespace {

/// Slow, obviously correct inside test: the winding number as the sum of the solid angles of
/// all triangles seen from q (Van Oosterom & Strackee), inside if it rounds to 1.
bool brute_force_inside(const Mesh& mesh, const Eigen::Vector3d& q) {
  double solid_angle = 0;
  for (int f = 0; f < mesh.face_count(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose() - q;
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1)).transpose() - q;
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2)).transpose() - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    solid_angle += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return solid_angle / (4 * std::numbers::pi) > 0.5;
}

using testing::transformed;

TEST(MassProperties, BoxFarFromTheOriginIsExact) {
  const Eigen::Vector3d offset(1e6, -2e6, 3e5);
  const Mesh box = transformed(make_box({2, 3, 5}), Eigen::Affine3d(Eigen::Translation3d(offset)));
  const MassProperties mp = mass_properties(box);
  EXPECT_NEAR(mp.volume, 30, 1e-6);
  EXPECT_NEAR(mp.surface_area, 2 * (6 + 10 + 15), 1e-6);
  EXPECT_LT((mp.center_of_mass - offset).norm(), 1e-8);
  EXPECT_FALSE(mp.center_is_surface_centroid);
  EXPECT_TRUE(mp.bounds.min().isApprox(offset - Eigen::Vector3d(1, 1.5, 2.5)));
}

TEST(MassProperties, RandomTetrahedraMatchTheClosedForm) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::Matrix<double, 4, 3> p;
    for (int i = 0; i < 12; ++i) p(i / 3, i % 3) = u(rng);
    const double six_volume = (p.row(1) - p.row(0)).dot((p.row(2) - p.row(0)).cross(p.row(3) - p.row(0)));
    if (std::abs(six_volume) < 0.1) continue;
    Mesh tet;
    tet.V = p;
    tet.F.resize(4, 3);
    // Faces outward for a positively oriented (0,1,2,3).
    tet.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
    const MassProperties mp = mass_properties(tet);
    EXPECT_NEAR(mp.volume, six_volume / 6, 1e-12);
    EXPECT_LT((mp.center_of_mass - p.colwise().mean().transpose()).norm(), 1e-12);
  }
}

TEST(MassProperties, RigidMotionsMoveTheCenterAndKeepTheVolume) {
  const Mesh base = make_sphere(1.5, 2);
  const Mesh sheared = transformed(base, Eigen::Affine3d(Eigen::Scaling(1.0, 0.5, 2.0)));  // an ellipsoid
  const MassProperties reference = mass_properties(sheared);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
    const Eigen::Affine3d T = Eigen::Translation3d(u(rng), u(rng), u(rng)) * q;
    const MassProperties mp = mass_properties(transformed(sheared, T));
    EXPECT_NEAR(mp.volume, reference.volume, 1e-10);
    EXPECT_NEAR(mp.surface_area, reference.surface_area, 1e-10);
    EXPECT_LT((mp.center_of_mass - T * reference.center_of_mass).norm(), 1e-10);
  }
}

TEST(MassProperties, InsideOutMeshHasNegativeVolumeAndTheSameCenter) {
  Mesh box = transformed(make_box({1, 1, 1}), Eigen::Affine3d(Eigen::Translation3d(1, 2, 3)));
  box.F.col(1).swap(box.F.col(2));
  const MassProperties mp = mass_properties(box);
  EXPECT_DOUBLE_EQ(mp.volume, -1);
  EXPECT_LT((mp.center_of_mass - Eigen::Vector3d(1, 2, 3)).norm(), 1e-14);
}

TEST(MassProperties, FlatMeshFallsBackToTheSurfaceCentroid) {
  // Two triangles of different areas in the plane z = 4: no volume.
  Mesh sheet;
  sheet.V.resize(5, 3);
  sheet.V << 0, 0, 4, 2, 0, 4, 0, 2, 4, 10, 0, 4, 10, 1, 4;
  sheet.F.resize(2, 3);
  sheet.F << 0, 1, 2, 1, 3, 4;
  const MassProperties mp = mass_properties(sheet);
  EXPECT_EQ(mp.volume, 0);
  EXPECT_TRUE(mp.center_is_surface_centroid);
  const double a1 = 2, a2 = 4;  // areas
  const Eigen::Vector3d c1(2.0 / 3, 2.0 / 3, 4), c2(22.0 / 3, 1.0 / 3, 4);
  EXPECT_LT((mp.center_of_mass - (a1 * c1 + a2 * c2) / (a1 + a2)).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(mp.surface_area, a1 + a2);
}

TEST(MassProperties, EmptyMeshHasNothing) {
  const MassProperties mp = mass_properties(Mesh{});
  EXPECT_EQ(mp.volume, 0);
  EXPECT_TRUE(mp.bounds.isEmpty());
  EXPECT_TRUE(mp.center_is_surface_centroid);
}

TEST(MassProperties, OutOfRangeIndexThrowsNamingTheFace) {
  Mesh box = make_box({1, 1, 1});
  box.F(5, 1) = 8;
  try {
    mass_properties(box);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.location(), "face 5");
  }
}

TEST(MassProperties, MatchesAStratifiedSamplingOfAGenusTwoSolid) {
  const Mesh mesh = load_mesh(reconfig::testing::cgal_mesh("eight.off"));
  const MassProperties mp = mass_properties(mesh);
  ASSERT_GT(mp.volume, 0);
  // One jittered sample per cell of a 24³ grid over the bounds, inside decided by brute force.
  const int cells = 24;
  const Eigen::Vector3d size = mp.bounds.sizes() / cells;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int inside = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k) {
        const Eigen::Vector3d q =
            mp.bounds.min() + Eigen::Vector3d((i + u(rng)) * size.x(), (j + u(rng)) * size.y(), (k + u(rng)) * size.z());
        if (brute_force_inside(mesh, q)) {
          ++inside;
          sum += q;
        }
      }
  const double estimate = inside * size.prod();
  EXPECT_NEAR(mp.volume, estimate, 0.03 * estimate);
  EXPECT_LT((mp.center_of_mass - sum / inside).norm(), 0.01 * mp.bounds.diagonal().norm());
  for (int k = 0; k < 3; ++k) {  // bounds are the vertices' extremes
    EXPECT_EQ(mp.bounds.min()[k], mesh.V.col(k).minCoeff());
    EXPECT_EQ(mp.bounds.max()[k], mesh.V.col(k).maxCoeff());
  }
}

}  // namespace
}  // namespace reconfig::geometry
