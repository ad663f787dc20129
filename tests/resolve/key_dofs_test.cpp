#include "reconfig/resolve/key_dofs.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <initializer_list>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/edits.h"
#include "resolve_scenes.h"
#include "support/random_scene.h"

namespace reconfig::resolve {
namespace {

/// A random scene whose moving parts have inner translation and rotation keys (turns of up to a
/// full turn, so segments turn by more than 90°), some keys moved off the even times.
scene::Reconfigurable scene_with_inner_keys(std::uint32_t seed) {
  scene::Reconfigurable scene = reconfig::testing::random_scene(seed, {.parts = 2, .moving = 2, .rotation_keys = 3});
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> inner(0.2, 0.8);
  for (const scene::Part& part : scene.parts) {
    scene::insert_key("move", part.name, scene::KeyKind::kTranslation, inner(random))->apply(scene);
    scene::insert_key("move", part.name, scene::KeyKind::kTranslation, 0.93)->apply(scene);
  }
  return scene;
}

TEST(KeyDofs, ListsInnerKeysAndTheHandlesThatShapeTheMotion) {
  const scene::Reconfigurable scene = scene_with_inner_keys(1);
  const std::vector<KeyDof> dofs = key_dofs(scene, 0, 0);
  // 4 translation keys: inner 1, 2 (point, in, out, time each), first key's out, last's in;
  // 3 rotation keys: inner 1 (rotation, time).
  int translation = 0, handles = 0, rotation = 0, time = 0;
  for (const KeyDof& dof : dofs) {
    translation += dof.kind == DofKind::kTranslation;
    handles += dof.kind == DofKind::kHandleIn || dof.kind == DofKind::kHandleOut;
    rotation += dof.kind == DofKind::kRotation;
    time += dof.kind == DofKind::kTime;
    if (dof.kind == DofKind::kTranslation || dof.kind == DofKind::kRotation) {
      EXPECT_GT(dof.key, 0);  // never an end key's point or rotation: those are the states'
    }
  }
  EXPECT_EQ(translation, 2);
  EXPECT_EQ(handles, 6);
  EXPECT_EQ(rotation, 1);
  EXPECT_EQ(time, 3);
  EXPECT_EQ(dof_coordinates(dofs), 2 * 3 + 6 * 3 + 3 + 3);
  EXPECT_EQ(dof_coordinates(key_dofs(scene, 0, 0, {.handles = false, .rotations = false, .times = false})), 6);
  scene::Reconfigurable still = scene;
  still.transitions[0].tracks.erase(still.parts[1].name);
  EXPECT_TRUE(key_dofs(still, 0, 1).empty());
}

/// The velocity of rest point p of the part at time t, for a twist column.
Eigen::Vector3d point_velocity(const Eigen::Matrix<double, 6, 1>& twist, const Eigen::Vector3d& y) {
  return twist.head<3>() + twist.tail<3>().cross(y);
}

/// The twist Jacobian of part 0 in transition 0 against central differences of displace_keys,
/// at a vertex of the part, at each of `times`.
void expect_jacobian_matches_finite_differences(const scene::Reconfigurable& scene, const std::vector<KeyDof>& dofs,
                                                std::initializer_list<double> times, const std::string& label) {
  const int n = dof_coordinates(dofs);
  const scene::Part& part = scene.parts[0];
  const Eigen::Vector3d p = part.mesh.V.row(0).transpose();
  for (double t : times) {
    const auto J = twist_jacobian(scene, 0, 0, dofs, t);
    const Eigen::Vector3d y = scene.pose_at(0, 0, t).apply(part.center, p);
    for (int k = 0; k < n; ++k) {
      const double h = 1e-6;
      const auto displaced = [&](double s) {
        scene::Reconfigurable moved = scene;
        Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
        step[k] = s;
        displace_keys(moved, 0, 0, dofs, step);
        return moved.pose_at(0, 0, t).apply(part.center, p);
      };
      const Eigen::Vector3d fd = (displaced(h) - displaced(-h)) / (2 * h);
      const Eigen::Vector3d analytic = point_velocity(J.col(k), y);
      EXPECT_LT((analytic - fd).norm(), 1e-5 * (1 + fd.norm())) << label << " t " << t << " coordinate " << k;
    }
  }
}

TEST(KeyDofs, TwistJacobianMatchesFiniteDifferencesOfEveryKind) {
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const scene::Reconfigurable scene = scene_with_inner_keys(seed);
    expect_jacobian_matches_finite_differences(scene, key_dofs(scene, 0, 0), {0.05, 0.3, 0.55, 0.77, 0.96},
                                               "seed " + std::to_string(seed));
  }
}

TEST(KeyDofs, EndKeysAreListedOnlyWhenAsked) {
  const scene::Reconfigurable scene = scene_with_inner_keys(3);
  int ends = 0;
  for (const KeyDof& dof : key_dofs(scene, 0, 0, {.end_keys = true})) {
    const bool end = dof.key == 0 || (dof.track == scene::KeyKind::kTranslation ? dof.key == 3 : dof.key == 2);
    if (end && (dof.kind == DofKind::kTranslation || dof.kind == DofKind::kRotation)) ++ends;
    if (end) {
      EXPECT_NE(dof.kind, DofKind::kTime);  // the ends stay at t = 0 and 1
    }
  }
  EXPECT_EQ(ends, 4);  // two translation keys, two rotation keys
}

TEST(KeyDofs, EndKeysMoveTheStatesAndEveryTransitionThroughThem) {
  for (std::uint32_t seed = 4; seed <= 8; ++seed) {
    scene::Reconfigurable scene = scene_with_inner_keys(seed);
    scene.transitions.push_back(testing::reversed_transition(scene.transitions[0], "back"));
    const std::vector<KeyDof> dofs = key_dofs(scene, 0, 0, {.end_keys = true});
    const int n = dof_coordinates(dofs);
    const scene::Part& part = scene.parts[0];
    // The Jacobian of the end keys matches finite differences, at the ends too.
    expect_jacobian_matches_finite_differences(scene, dofs, {0.0, 0.04, 0.5, 0.97, 1.0}, "seed " + std::to_string(seed));
    // A step on every coordinate: the states hold the new end poses, and "back" starts and
    // ends where "move" ends and starts.
    scene::Reconfigurable moved = scene;
    displace_keys(moved, 0, 0, dofs, Eigen::VectorXd::Constant(n, 0.05));
    const motion::Pose start = moved.pose_at(0, 0, 0.0), end = moved.pose_at(0, 0, 1.0);
    EXPECT_GT((start.translation - scene.pose_at(0, 0, 0.0).translation).norm(), 0.01);
    const motion::Pose in_start = moved.states[moved.find_state("start")].pose_of(part.name);
    EXPECT_LT((in_start.translation - start.translation).norm(), 1e-12);
    EXPECT_LT(in_start.rotation.angularDistance(start.rotation), 1e-9);
    EXPECT_LT((moved.pose_at(1, 0, 1.0).translation - start.translation).norm(), 1e-12);
    EXPECT_LT((moved.pose_at(1, 0, 0.0).translation - end.translation).norm(), 1e-12);
    EXPECT_LT(moved.pose_at(1, 0, 0.0).rotation.angularDistance(end.rotation), 1e-9);
  }
}

TEST(KeyDofs, DisplacingATimePastItsNeighbourIsRefused) {
  scene::Reconfigurable scene = scene_with_inner_keys(2);
  const std::vector<KeyDof> dofs = key_dofs(scene, 0, 0, {.handles = false, .rotations = false, .times = true});
  Eigen::VectorXd step = Eigen::VectorXd::Zero(dof_coordinates(dofs));
  step[3] = 2.0;  // the first inner key's time, far past the next key
  EXPECT_THROW(displace_keys(scene, 0, 0, dofs, step), InputError);
}

}  // namespace
}  // namespace reconfig::resolve
