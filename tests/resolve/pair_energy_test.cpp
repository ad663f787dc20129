#include "reconfig/resolve/pair_energy.h"

#include <gtest/gtest.h>

#include <numbers>

#include "reconfig/resolve/hints.h"
#include "reconfig/resolve/key_dofs.h"
#include "resolve_scenes.h"
#include "support/random_scene.h"

namespace reconfig::resolve {
namespace {

using testing::two_part_scene;

TEST(PairEnergy, ASpherePassingThroughASlabIntegratesItsCircles) {
  // A unit sphere falls through the top face of a big box at constant speed: at depth s below
  // the face the contour is a circle of radius sqrt(1 − (1 − s)²)... until the sphere is inside.
  const scene::Reconfigurable scene =
      two_part_scene(geometry::make_box({6, 6, 6}), geometry::make_sphere(1.0, 4), {{0, 0, 4}, {0, 0, 3}, {0, 0, 2}});
  ShapeCache shapes;
  PairEnergyRequest request;
  request.part_a = 1;
  request.part_b = 0;
  const PairEnergy energy = pair_energy(scene, shapes, request);
  ASSERT_GT(energy.contour_energy, 0);
  // The reference: the same integral from the exact circles, with the track's own timing
  // (x(t) is a cubic; sampled densely here).
  double reference = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) / n;
    const double z = scene.pose_at(0, 1, t).translation.z();  // the sphere's center
    const double d = z - 3.0;                                  // height above the face
    if (std::abs(d) < 1) reference += 2 * std::numbers::pi * std::sqrt(1 - d * d) / n;
  }
  EXPECT_NEAR(energy.contour_energy, reference, 0.02 * reference);  // mesh discretization + 1 %
  EXPECT_NEAR(energy.severity_time, 0.5, 0.05);  // the great circle is cut at the middle
  EXPECT_GT(energy.penetration_energy, 0);
}

TEST(PairEnergy, RefinementChangesItByLessThanTheAccuracy) {
  const scene::Reconfigurable scene = testing::hook_scene();
  ShapeCache shapes;
  PairEnergyRequest request;
  request.part_a = 1;
  request.part_b = 0;
  const PairEnergy energy = pair_energy(scene, shapes, request);
  ASSERT_GT(energy.energy, 0);
  request.min_intervals = request.max_intervals = static_cast<int>(energy.samples.size() - 1) * 4;
  const PairEnergy finer = pair_energy(scene, shapes, request);
  EXPECT_NEAR(energy.energy, finer.energy, 0.015 * finer.energy);
}

/// The accuracy on random two-part scenes (turning, colliding or passing close): the energy
/// the stopping rule settles on is within the accuracy of one on four times its samples.
TEST(PairEnergy, RefinementChangesItByLessThanTheAccuracyOnRandomScenes) {
  int checked = 0;
  for (std::uint32_t seed = 1; seed <= 30 && checked < 8; ++seed) {
    const scene::Reconfigurable scene =
        reconfig::testing::random_scene(seed, {.parts = 2, .moving = 2, .spread = 0.3, .rotation_keys = 3});
    ShapeCache shapes;
    PairEnergyRequest request{.part_a = 0, .part_b = 1, .proximity_reach = 0.002};
    const PairEnergy energy = pair_energy(scene, shapes, request);
    if (energy.energy == 0) continue;
    request.min_intervals = request.max_intervals = static_cast<int>(energy.samples.size() - 1) * 4;
    const PairEnergy finer = pair_energy(scene, shapes, request);
    EXPECT_NEAR(energy.energy, finer.energy, 0.015 * finer.energy) << "seed " << seed;
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

TEST(PairEnergy, FarApartPartsHaveNone) {
  const scene::Reconfigurable scene =
      two_part_scene(geometry::make_box({1, 1, 1}), geometry::make_box({1, 1, 1}), {{3, 0, 0}, {3, 3, 0}, {3, 6, 0}});
  ShapeCache shapes;
  const PairEnergy energy = pair_energy(scene, shapes, {.part_a = 0, .part_b = 1});
  EXPECT_EQ(energy.energy, 0);
  EXPECT_EQ(energy.severity_time, 0.5);
}

/// ∂E/∂(every coordinate) by the chain rule against central differences of E itself, on fixed
/// samples (so that E is a smooth function of the keys).
TEST(PairEnergy, ChainRuleMatchesFiniteDifferencesForEveryKindOfDof) {
  int checked = 0;
  for (std::uint32_t seed = 1; seed <= 40 && checked < 60; ++seed) {
    scene::Reconfigurable scene = reconfig::testing::random_scene(seed, {.parts = 2, .moving = 2, .spread = 0.25, .rotation_keys = 3});
    scene::insert_key("move", scene.parts[0].name, scene::KeyKind::kTranslation, 0.45)->apply(scene);
    ShapeCache shapes;
    PairEnergyRequest request{.part_a = 0, .part_b = 1, .min_intervals = 24, .max_intervals = 24};
    const PairEnergy energy = pair_energy(scene, shapes, request);
    if (energy.energy == 0) continue;
    for (int part : {0, 1}) {
      const std::vector<KeyDof> dofs = key_dofs(scene, 0, part);
      const Eigen::VectorXd g = energy_gradient(scene, 0, part, dofs, energy, part == 0);
      for (int k = 0; k < dof_coordinates(dofs); k += 2) {
        const auto E = [&](double s) {
          scene::Reconfigurable moved = scene;
          Eigen::VectorXd step = Eigen::VectorXd::Zero(dof_coordinates(dofs));
          step[k] = s;
          displace_keys(moved, 0, part, dofs, step);
          return pair_energy(moved, shapes, request).energy;
        };
        const double h = 1e-6;
        const double fd = (E(h) - E(-h)) / (2 * h);
        EXPECT_NEAR(g[k], fd, 2e-3 * (1 + std::abs(fd))) << "seed " << seed << " part " << part << " coordinate " << k;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 60);
}

}  // namespace
}  // namespace reconfig::resolve
