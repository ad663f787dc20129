#include "reconfig/collision/collision_service.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "reconfig/collision/consolidate.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/part_edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/scene/transition_edits.h"
#include "support/test_data.h"

namespace reconfig::collision {
namespace {

using namespace std::chrono_literals;

scene::Reconfigurable bench_table() {
  return scene::load_scene(testing::source_dir() / "examples" / "bench-table" / "scene.json");
}

scene::DirtySet everything() {
  scene::DirtySet dirty;
  dirty.structure_changed = true;
  return dirty;
}

/// Lifts the backrest's path in "unfold" (as the collision-free "unfold_lifted" does).
std::unique_ptr<scene::Command> lift_backrest() {
  return scene::set_translation_key("unfold", "backrest", 1, {0.5, {0, 0.1, 0.45}, {0, 0.05, 0.45}, {0, 0.15, 0.45}});
}

TEST(CollisionService, PublishesTheIntervalsOfEveryTransition) {
  CollisionService service;
  EXPECT_EQ(service.snapshot()->version, 0u);
  const std::uint64_t version = service.submit(std::make_shared<scene::Reconfigurable>(bench_table()), everything());
  ASSERT_TRUE(service.wait_until_complete(60s));
  const auto snapshot = service.snapshot();
  EXPECT_EQ(snapshot->version, version);
  ASSERT_EQ(snapshot->transitions.size(), 2u);
  EXPECT_EQ(snapshot->transitions[0].name, "unfold");
  EXPECT_EQ(snapshot->transitions[0].intervals.size(), 2u);  // backrest × each armrest
  EXPECT_GE(snapshot->transitions[0].frames.size(), snapshot->transitions[0].intervals.size());
  for (const CollisionInterval& frame : snapshot->transitions[0].frames) EXPECT_LE(frame.duration(), 0.01 + 1e-12);
  EXPECT_TRUE(snapshot->transitions[1].intervals.empty());
  for (const IntervalDiffEntry& change : snapshot->transitions[0].changes) EXPECT_EQ(change.change, IntervalChange::kAppeared);
}

// Every published picture, also the early ones while later transitions are still waiting for
// detection, names each entry's transition (the UI finds entries by index).
// An appended transition is detected on its own: the results of the others stand (reported
// unchanged, where a detection from scratch reports each interval as appeared).
TEST(CollisionService, AnAppendedTransitionIsDetectedAlone) {
  CollisionService service;
  auto scene = std::make_shared<scene::Reconfigurable>(bench_table());
  service.submit(scene, everything());
  ASSERT_TRUE(service.wait_until_complete(60s));
  ASSERT_EQ(service.snapshot()->transitions[0].changes.size(), 2u);
  for (const IntervalDiffEntry& change : service.snapshot()->transitions[0].changes)
    ASSERT_EQ(change.change, IntervalChange::kAppeared);
  auto next = std::make_shared<scene::Reconfigurable>(*scene);
  scene::History history;
  const scene::DirtySet dirty = history.execute(*next, scene::duplicate_transition("unfold", "unfold_again"));
  ASSERT_EQ(dirty.added_transitions, std::vector<int>{2});
  service.submit(next, dirty);
  ASSERT_TRUE(service.wait_until_complete(60s));
  const auto snapshot = service.snapshot();
  ASSERT_EQ(snapshot->transitions.size(), 3u);
  EXPECT_EQ(snapshot->transitions[0].intervals.size(), 2u);
  for (const IntervalDiffEntry& change : snapshot->transitions[0].changes)  // not detected again
    EXPECT_EQ(change.change, IntervalChange::kUnchanged);
  EXPECT_EQ(snapshot->transitions[0].changes.size(), 2u);
  EXPECT_EQ(snapshot->transitions[2].name, "unfold_again");
  EXPECT_EQ(snapshot->transitions[2].intervals.size(), 2u);
  for (const IntervalDiffEntry& change : snapshot->transitions[2].changes) EXPECT_EQ(change.change, IntervalChange::kAppeared);
  // Its undo starts over, and finds what a detection from scratch finds.
  auto back = std::make_shared<scene::Reconfigurable>(*next);
  const scene::DirtySet undone = history.undo(*back);
  EXPECT_TRUE(undone.structure_changed);
  service.submit(back, undone);
  ASSERT_TRUE(service.wait_until_complete(60s));
  ASSERT_EQ(service.snapshot()->transitions.size(), 2u);
  EXPECT_EQ(service.snapshot()->transitions[0].intervals.size(), 2u);
}

// Deleting a part renumbers those after it: from the submission on, no published picture names
// a part by its old index (the UI looks parts up by index).
TEST(CollisionService, NoPictureAfterARenumberingUsesTheOldIndices) {
  CollisionService service;
  auto scene = std::make_shared<scene::Reconfigurable>(bench_table());
  service.submit(scene, everything());
  ASSERT_TRUE(service.wait_until_complete(60s));
  const int last = scene->find_part("armrest_right");
  ASSERT_EQ(last, static_cast<int>(scene->parts.size()) - 1);
  bool names_last = false;  // the picture before names the last part: the index at stake
  for (const CollisionInterval& interval : service.snapshot()->transitions[0].intervals)
    names_last = names_last || std::count(interval.parts.begin(), interval.parts.end(), last) > 0;
  ASSERT_TRUE(names_last);
  auto next = std::make_shared<scene::Reconfigurable>(*scene);
  scene::History history;
  const scene::DirtySet dirty = history.execute(*next, scene::delete_part("armrest_left"));
  ASSERT_TRUE(dirty.structure_changed);
  service.submit(next, dirty);
  for (int polls = 0; polls < 20000; ++polls) {
    const auto snapshot = service.snapshot();
    for (const TransitionSnapshot& transition : snapshot->transitions)
      for (const CollisionInterval& interval : transition.intervals)
        for (int part : interval.parts) ASSERT_LT(part, static_cast<int>(next->parts.size())) << "poll " << polls;
    if (snapshot->complete) break;
    std::this_thread::sleep_for(50us);
  }
  ASSERT_TRUE(service.wait_until_complete(60s));
  ASSERT_EQ(service.snapshot()->transitions[0].intervals.size(), 1u);  // backrest × armrest_right
  EXPECT_EQ(service.snapshot()->transitions[0].intervals[0].parts,
            (std::vector<int>{next->find_part("backrest"), next->find_part("armrest_right")}));
}

TEST(CollisionService, EveryPublishedEntryNamesItsTransition) {
  CollisionService service;
  service.submit(std::make_shared<scene::Reconfigurable>(bench_table()), everything());
  for (int polls = 0; polls < 2000; ++polls) {
    const auto snapshot = service.snapshot();
    for (std::size_t t = 0; t < snapshot->transitions.size(); ++t) {
      EXPECT_EQ(snapshot->transitions[t].transition, static_cast<int>(t));
      EXPECT_FALSE(snapshot->transitions[t].name.empty());
    }
    if (snapshot->complete) break;
    std::this_thread::sleep_for(100us);
  }
  ASSERT_TRUE(service.wait_until_complete(60s));
}

TEST(CollisionService, AnEditMakesTheCollisionDisappearAndUndoBringsItBack) {
  CollisionService service;
  scene::Reconfigurable scene = bench_table();
  service.submit(std::make_shared<scene::Reconfigurable>(scene), everything());
  ASSERT_TRUE(service.wait_until_complete(60s));

  scene::History history;
  history.execute(scene, scene::insert_key("unfold", "backrest", scene::KeyKind::kTranslation, 0.5));
  service.submit(std::make_shared<scene::Reconfigurable>(scene), {});  // inserting keeps the motion
  scene::DirtySet dirty = history.execute(scene, lift_backrest());
  service.submit(std::make_shared<scene::Reconfigurable>(scene), dirty);
  ASSERT_TRUE(service.wait_until_complete(60s));
  auto snapshot = service.snapshot();
  EXPECT_TRUE(snapshot->transitions[0].intervals.empty());
  ASSERT_EQ(snapshot->transitions[0].changes.size(), 2u);
  for (const IntervalDiffEntry& change : snapshot->transitions[0].changes)
    EXPECT_EQ(change.change, IntervalChange::kDisappeared);

  dirty = history.undo(scene);
  service.submit(std::make_shared<scene::Reconfigurable>(scene), dirty);
  ASSERT_TRUE(service.wait_until_complete(60s));
  snapshot = service.snapshot();
  EXPECT_EQ(snapshot->transitions[0].intervals.size(), 2u);
}

/// Many quick submissions (an edit drag): the UI never waits, older work is dropped, and the
/// final picture equals a detection from scratch of the final design.
TEST(CollisionService, RapidEditsEndInTheSameResultAsAFreshDetection) {
  CollisionService service;
  scene::Reconfigurable scene = bench_table();
  service.submit(std::make_shared<scene::Reconfigurable>(scene), everything());
  scene::History history;
  history.execute(scene, scene::insert_key("unfold", "backrest", scene::KeyKind::kTranslation, 0.5));
  std::uint64_t last = 0;
  for (int step = 0; step < 30; ++step) {
    const double z = 0.3 + 0.3 * step / 29.0;
    const scene::DirtySet dirty = history.execute(
        scene, scene::set_translation_key("unfold", "backrest", 1, {0.5, {0, 0.1, z}, {0, 0.05, z}, {0, 0.15, z}}));
    last = service.submit(std::make_shared<scene::Reconfigurable>(scene), dirty);
    EXPECT_NE(service.snapshot(), nullptr);  // readable at any time
  }
  ASSERT_TRUE(service.wait_until_complete(120s));
  const auto snapshot = service.snapshot();
  EXPECT_EQ(snapshot->version, last);
  SpacetimeDetector fresh(0, {});
  ASSERT_TRUE(fresh.detect(scene, build_body_trees(scene)));
  const auto expected = consolidate(fresh.groups(), fresh.containments());
  ASSERT_EQ(snapshot->transitions[0].intervals.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(snapshot->transitions[0].intervals[i].t0, expected[i].t0);
    EXPECT_EQ(snapshot->transitions[0].intervals[i].t1, expected[i].t1);
    EXPECT_EQ(snapshot->transitions[0].intervals[i].box.min(), expected[i].box.min());
    EXPECT_EQ(snapshot->transitions[0].intervals[i].box.max(), expected[i].box.max());
    EXPECT_EQ(snapshot->transitions[0].intervals[i].parts, expected[i].parts);
  }
}

}  // namespace
}  // namespace reconfig::collision
