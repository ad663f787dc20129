#include "reconfig/resolve/auto_resolve.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/scene_file.h"
#include "resolve_scenes.h"
#include "support/test_data.h"

namespace reconfig::resolve {
namespace {

bool collides(const scene::Reconfigurable& scene, int transition) {
  collision::CollisionRequest request;
  request.transitions = {transition};
  return collision::detect_collisions(scene, request).any_collision();
}

bool reference_collides(const scene::Reconfigurable& scene, int transition) {
  collision::ReferenceCheckRequest request;
  request.transitions = {transition};
  return collision::reference_check(scene, request).any_collision();
}

TEST(AutoResolve, BenchTableUnfoldEndsCollisionFreeWithoutTouchingTheStates) {
  const scene::Reconfigurable scene = scene::load_scene(reconfig::testing::source_dir() / "examples/bench-table/scene.json");
  const int unfold = scene.find_transition("unfold");
  ASSERT_TRUE(collides(scene, unfold));
  AutoResolveRequest request;
  request.transition = unfold;
  const AutoResolveResult result = auto_resolve(scene, request);
  EXPECT_TRUE(result.collision_free) << result.stopped_because;
  EXPECT_FALSE(collides(result.scene, unfold));
  EXPECT_FALSE(reference_collides(result.scene, unfold));
  ASSERT_EQ(result.scene.states.size(), scene.states.size());
  for (std::size_t s = 0; s < scene.states.size(); ++s)
    for (const auto& [part, pose] : scene.states[s].poses) {
      const motion::Pose after = result.scene.states[s].pose_of(part);
      EXPECT_EQ(after.translation, pose.translation) << part;
      EXPECT_EQ(after.rotation.coeffs(), pose.rotation.coeffs()) << part;
    }
  ASSERT_FALSE(result.rounds.empty());
  EXPECT_FALSE(result.rounds.front().inserted_keys.empty());  // unfold has no inner key
  EXPECT_LT(result.rounds.front().energy_after, result.rounds.front().energy_before);
}

TEST(AutoResolve, TheHookIsLiftedOverTheOther) {
  const scene::Reconfigurable scene = testing::hook_scene();
  ASSERT_TRUE(collides(scene, 0));
  const AutoResolveResult result = auto_resolve(scene, {});
  ASSERT_TRUE(result.collision_free) << result.stopped_because;
  // Lifted over the tip (the tips overlap by 0.2 in z) while it keeps sliding forward: x(t)
  // never goes back (pushing back cannot resolve it: the end states are fixed).
  double highest = 0, previous_x = -1e9;
  for (int i = 0; i <= 200; ++i) {
    const Eigen::Vector3d x = result.scene.pose_at(0, 1, i / 200.0).translation;
    highest = std::max(highest, x.z());
    EXPECT_GE(x.x(), previous_x - 1e-9) << "t " << i / 200.0;
    previous_x = x.x();
  }
  EXPECT_GT(highest, 0.2);
}

TEST(AutoResolve, ASmallBoxPassingThroughABigOneIsRoutedAround) {
  const scene::Reconfigurable scene = testing::box_through_box_scene();
  ASSERT_TRUE(collides(scene, 0));
  const AutoResolveResult result = auto_resolve(scene, {});
  EXPECT_TRUE(result.collision_free) << result.stopped_because;
  EXPECT_FALSE(reference_collides(result.scene, 0));
}

TEST(AutoResolve, TheHastyKitchenIsResolvedByRetimingItsPullouts) {
  // The pull-outs slide out while the (screw-driven) doors are still swinging open: moving
  // them aside runs them into the carcass; holding them back (keys moved in time and space)
  // resolves it, as the careful choreography `open` does.
  const scene::Reconfigurable scene = scene::load_scene(reconfig::testing::source_dir() / "examples/kitchen/scene.json");
  const int hasty = scene.find_transition("open_hasty");
  ASSERT_TRUE(collides(scene, hasty));
  const AutoResolveResult result = auto_resolve(scene, {.transition = hasty, .move_times = true});
  EXPECT_TRUE(result.collision_free) << result.stopped_because;
  EXPECT_FALSE(reference_collides(result.scene, hasty));
}

/// A box sliding along x that ends half inside a still box (the end state itself collides),
/// and a transition "back" from that state to the start.
scene::Reconfigurable end_state_inside_scene() {
  scene::Reconfigurable scene = testing::two_part_scene(geometry::make_box({1, 1, 1}), geometry::make_box({0.5, 0.5, 0.5}),
                                                        {{-3, 0, 0}, {-1.5, 0, 0}, {-0.6, 0, 0}});
  scene.transitions.push_back(testing::reversed_transition(scene.transitions[0], "back"));
  return scene;
}

TEST(AutoResolve, AStateThatCollidesIsMovedOnlyWhenStatesMayMove) {
  const scene::Reconfigurable scene = end_state_inside_scene();
  ASSERT_TRUE(collides(scene, 0));
  ASSERT_TRUE(collides(scene, 1));  // the same state, where "back" starts
  const AutoResolveResult fixed = auto_resolve(scene, {.max_rounds = 4});
  EXPECT_FALSE(fixed.collision_free);  // the collision at t = 1 is the state's own
  const AutoResolveResult freed = auto_resolve(scene, {.max_rounds = 8, .move_states = true});
  ASSERT_TRUE(freed.collision_free) << freed.stopped_because;
  EXPECT_FALSE(reference_collides(freed.scene, 0));
  // The part moved in "end", and "back" starts there: it was re-checked, and is free too.
  bool moved = false;
  for (const ResolveRound& round : freed.rounds)
    for (const std::string& what : round.moved_states) moved |= what == "mover in end";
  EXPECT_TRUE(moved);
  ASSERT_EQ(freed.rechecked.size(), 1u);
  EXPECT_EQ(freed.rechecked[0].first, "back");
  EXPECT_EQ(freed.rechecked[0].second, 0);
  EXPECT_FALSE(collides(freed.scene, 1));
  const motion::Pose end = freed.scene.states[freed.scene.find_state("end")].pose_of("mover");
  EXPECT_LT((freed.scene.pose_at(1, 1, 0.0).translation - end.translation).norm(), 1e-12);
  EXPECT_LT((freed.scene.pose_at(0, 1, 1.0).translation - end.translation).norm(), 1e-12);
  // The start state stays where it was: it did not collide.
  EXPECT_EQ(freed.scene.states[freed.scene.find_state("start")].pose_of("mover").translation, Eigen::Vector3d(-3, 0, 0));
}

TEST(AutoResolve, CancellingStops) {
  const AutoResolveResult result = auto_resolve(testing::hook_scene(), {.progress = [](double) { return false; }});
  EXPECT_TRUE(result.cancelled);
  EXPECT_FALSE(result.collision_free);
}

/// Two-part scenes with one inner key, placed at random so that the mover collides with the
/// still part on the way, where lifting the key over the still part is collision-free.
TEST(AutoResolve, ResolvesAtLeastNinetyPercentOfRandomTwoPartScenes) {
  std::mt19937 random(21);
  std::uniform_real_distribution<double> unit(0, 1);
  int colliding = 0, resolved = 0;
  std::string unresolved;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d still_size(0.6 + unit(random), 0.6 + unit(random), 0.3 + 0.5 * unit(random));
    const geometry::Mesh mover = trial % 2 ? geometry::make_sphere(0.15 + 0.15 * unit(random), 2)
                                           : geometry::make_box({0.3 + 0.2 * unit(random), 0.2 + 0.2 * unit(random), 0.2});
    const Eigen::Vector3d middle(0.4 * (unit(random) - 0.5), 0.4 * (unit(random) - 0.5), 0.6 * (unit(random) - 0.5));
    const scene::Reconfigurable scene = testing::two_part_scene(
        geometry::make_box(still_size), mover, {{-2.5, middle.y(), middle.z()}, middle, {2.5, -middle.y(), middle.z()}});
    if (!collides(scene, 0)) continue;
    ++colliding;
    const AutoResolveResult result = auto_resolve(scene, {});
    resolved += result.collision_free;
    if (!result.collision_free) unresolved += " trial " + std::to_string(trial) + ": " + result.stopped_because + ";";
  }
  ASSERT_GE(colliding, 15);
  EXPECT_GE(resolved, 0.9 * colliding) << unresolved;
  std::printf("resolved %d of %d colliding scenes;%s\n", resolved, colliding, unresolved.c_str());
}

}  // namespace
}  // namespace reconfig::resolve
