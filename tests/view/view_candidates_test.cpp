#include "reconfig/view/view_candidates.h"

#include <gtest/gtest.h>

#include <cmath>

#include "reconfig/geometry/primitives.h"

namespace reconfig::view {
namespace {

scene::Reconfigurable sliding_box(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  scene::Reconfigurable scene;
  scene::Part part;
  part.name = "box";
  part.source = scene::EditedMesh{};
  part.mesh = geometry::make_box(Eigen::Vector3d(1, 2, 3));
  part.center = scene::part_center(part.mesh) + Eigen::Vector3d(0.3, 0, 0);  // a pivot off the center
  scene.parts = {part};
  scene::KeyframedTrack track;
  track.translation.push_back({0.0, from, from, from + (to - from) / 3});
  track.translation.push_back({1.0, to, to - (to - from) / 3, to});
  track.rotation.push_back({0.0, Eigen::Quaterniond::Identity()});
  track.rotation.push_back({1.0, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()))});
  scene.states = {{"a", {}}, {"b", {}}};
  scene.transitions.push_back({"move", "a", "b", true, {{"box", track}}});
  return scene;
}

TEST(PartDisplacement, IsTheCenterOfMassTravelIncludingTheTurnAboutAnOffCenterPivot) {
  const scene::Reconfigurable scene = sliding_box({0, 0, 0}, {2, 1, 0});
  // Half a turn about a pivot 0.3 along +x of the center of mass carries the center 0.6 along +x.
  const Eigen::Vector3d r = part_displacement(scene, 0, 0, 0, 1);
  EXPECT_NEAR((r - Eigen::Vector3d(2 + 0.6, 1, 0)).norm(), 0, 1e-9) << r.transpose();
  EXPECT_NEAR(part_displacement(scene, 0, 0, 0.5, 0.5).norm(), 0, 1e-12);
}

TEST(MotionNormalDirections, AreBothSidesOfTheCrossProduct) {
  const auto normals = motion_normal_directions({2, 0, 0}, {0, 0.5, 0});
  ASSERT_TRUE(normals);
  EXPECT_NEAR(((*normals)[0] - Eigen::Vector3d::UnitZ()).norm(), 0, 1e-12);
  EXPECT_NEAR(((*normals)[1] + Eigen::Vector3d::UnitZ()).norm(), 0, 1e-12);
}

TEST(MotionNormalDirections, AreNoneForParallelMotionsOrAStillPart) {
  EXPECT_FALSE(motion_normal_directions({1, 0, 0}, {-2, 0, 0}));
  EXPECT_FALSE(motion_normal_directions({1, 0, 0}, {1, 0.001, 0}));
  EXPECT_FALSE(motion_normal_directions({1, 0, 0}, {0, 0, 0}));
  EXPECT_FALSE(motion_normal_directions({1, 0, 0}, {0, 1e-6, 0}));  // one part all but still
  EXPECT_TRUE(motion_normal_directions({1, 0, 0}, {1, 0.1, 0}));
}

// Uniform on the sphere: the mean is near 0 and each octant (or, on the hemisphere, each
// quadrant of azimuth) and each band of equal height holds its share (Archimedes).
TEST(RandomViewDirections, AreUnitAndUniformOnTheSphereAndHemisphere) {
  for (bool hemisphere : {false, true}) {
    const int n = 20000;
    const std::vector<Eigen::Vector3d> directions = random_view_directions(n, hemisphere, 7);
    ASSERT_EQ(directions.size(), static_cast<std::size_t>(n));
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::array<int, 8> octants{};
    std::array<int, 4> bands{};
    for (const Eigen::Vector3d& d : directions) {
      ASSERT_NEAR(d.norm(), 1, 1e-12);
      if (hemisphere) {
        ASSERT_GE(d.z(), 0);
      }
      mean += d / n;
      ++octants[(d.x() > 0) + 2 * (d.y() > 0) + 4 * (d.z() > 0)];
      const double lo = hemisphere ? 0 : -1;
      ++bands[std::min(3, static_cast<int>((d.z() - lo) / (1 - lo) * 4))];
    }
    EXPECT_NEAR(mean.x(), 0, 0.02);
    EXPECT_NEAR(mean.y(), 0, 0.02);
    EXPECT_NEAR(mean.z(), hemisphere ? 0.5 : 0, 0.02);
    const int octant_share = hemisphere ? n / 4 : n / 8;
    for (int o = hemisphere ? 4 : 0; o < 8; ++o) EXPECT_NEAR(octants[o], octant_share, 0.06 * octant_share);
    for (int band : bands) EXPECT_NEAR(band, n / 4, 0.06 * n / 4);
  }
  EXPECT_EQ(random_view_directions(10, true, 3), random_view_directions(10, true, 3));
  EXPECT_NE(random_view_directions(10, true, 3), random_view_directions(10, true, 4));
}

TEST(AxisViewDirections, LeaveOutBelowOnTheHemisphere) {
  EXPECT_EQ(axis_view_directions(false).size(), 6u);
  const std::vector<Eigen::Vector3d> north = axis_view_directions(true);
  EXPECT_EQ(north.size(), 5u);
  for (const Eigen::Vector3d& d : north) EXPECT_GE(d.z(), 0);
}

}  // namespace
}  // namespace reconfig::view
