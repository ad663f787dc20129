#pragma once
// Checks shared by the tests of the list edits: undo restores the design exactly, redo gives
// the edit again, and refusals change nothing.

#include <gtest/gtest.h>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/history.h"
#include "same_design.h"

namespace reconfig::scene {

/// Executes `command` on `scene`, checks that undo gives `scene` back exactly and that redo
/// gives the edited design again, then undoes; returns the dirty set and the edited design.
inline std::pair<DirtySet, Reconfigurable> round_trip(Reconfigurable& scene, std::unique_ptr<Command> command) {
  const Reconfigurable original = scene;
  History history;
  const DirtySet dirty = history.execute(scene, std::move(command));
  const Reconfigurable edited = scene;
  EXPECT_FALSE(same_design(scene, original)) << "the edit changed nothing";
  const DirtySet undone = history.undo(scene);
  if (dirty.added_transitions.empty()) {
    EXPECT_EQ(undone.structure_changed, dirty.structure_changed);
    EXPECT_EQ(undone.ranges, dirty.ranges);
  } else {
    EXPECT_TRUE(undone.structure_changed);  // taking the appended transitions away again
  }
  EXPECT_TRUE(same_design(scene, original));
  history.redo(scene);
  EXPECT_TRUE(same_design(scene, edited));
  history.undo(scene);
  EXPECT_TRUE(same_design(scene, original));
  return {dirty, edited};
}

/// Executing `command` throws an InputError whose message contains `words`, and changes nothing.
inline void expect_refused(Reconfigurable& scene, std::unique_ptr<Command> command, const std::string& words) {
  const Reconfigurable original = scene;
  History history;
  try {
    history.execute(scene, std::move(command));
    ADD_FAILURE() << "not refused";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
  EXPECT_TRUE(same_design(scene, original));
  EXPECT_FALSE(history.can_undo());
}

}  // namespace reconfig::scene
