#include "reconfig/resolve/hints.h"

#include <gtest/gtest.h>

#include "reconfig/collision/detect_collisions.h"
#include "reconfig/scene/edits.h"
#include "resolve_scenes.h"

namespace reconfig::resolve {
namespace {

std::vector<collision::CollisionInterval> intervals_of(const scene::Reconfigurable& scene) {
  const collision::CollisionResult result = collision::detect_collisions(scene);
  return result.transitions.at(0).intervals;
}

const Hint* find_hint(const HintResult& result, DofKind kind, int key) {
  for (const Hint& hint : result.hints)
    if (hint.dof.kind == kind && hint.dof.key == key) return &hint;
  return nullptr;
}

TEST(Hints, TheHookIsToldToLiftNotToPushBack) {
  const scene::Reconfigurable scene = testing::hook_scene();
  const auto intervals = intervals_of(scene);
  ASSERT_FALSE(intervals.empty());  // the tips do cross
  ShapeCache shapes;
  const HintResult result = compute_hints(scene, shapes, {.transition = 0, .part = 1, .intervals = intervals});
  ASSERT_GT(result.energy, 0);
  const Hint* middle = find_hint(result, DofKind::kTranslation, 1);
  ASSERT_NE(middle, nullptr);
  // The spacetime contact normal points up: the z component dominates the x one.
  EXPECT_GT(middle->direction[2], 0.7) << middle->direction.transpose();
  EXPECT_LT(middle->slope, 0);
  EXPECT_GT(result.severity_time, 0.3);
  EXPECT_LT(result.severity_time, 0.7);
}

TEST(Hints, ABoxWhollyInsideAnotherGetsADirectionOut) {
  const scene::Reconfigurable scene = testing::box_through_box_scene();
  // Only the stretch where the small box is wholly inside: no contour at all there.
  collision::CollisionInterval inside;
  inside.t0 = 0.42;
  inside.t1 = 0.58;
  inside.parts = {0, 1};
  ShapeCache shapes;
  const HintResult result =
      compute_hints(scene, shapes, {.transition = 0, .part = 1, .intervals = {inside}, .time_margin = 0});
  ASSERT_GT(result.energy, 0);
  const Hint* middle = find_hint(result, DofKind::kTranslation, 1);
  ASSERT_NE(middle, nullptr);
  EXPECT_GT(middle->gradient.norm(), 0);
  EXPECT_LT(middle->slope, 0);
}

TEST(Hints, APartWithoutKeysGetsNoneButItsEnergy) {
  const scene::Reconfigurable scene = testing::hook_scene();
  ShapeCache shapes;
  const HintResult result = compute_hints(scene, shapes, {.transition = 0, .part = 0, .intervals = intervals_of(scene)});
  EXPECT_GT(result.energy, 0);
  EXPECT_TRUE(result.hints.empty());
}

}  // namespace
}  // namespace reconfig::resolve
