#pragma once
/// @file
/// A headless studio on a private copy of the bench-table with `unfold` open and its
/// collisions (the backrest against both armrests) detected.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>

#include "studio_test_util.h"

namespace reconfig::studio {

class BenchTableUnfold : public ::testing::Test {
 protected:
  void SetUp() override {
    StudioOptions options;
    options.autosave_interval = std::chrono::milliseconds(0);
    frontend_ = std::make_unique<HeadlessFrontend>(1000, 700, options);
    ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
    unfold_ = scene().find_transition("unfold");
    studio().open_transition(unfold_);
    frontend_->run_frame();
    ASSERT_TRUE(frontend_->run_until_collisions_current(std::chrono::milliseconds(60000)));
  }

  Studio& studio() { return frontend_->studio(); }
  const scene::Reconfigurable& scene() { return studio().document()->scene(); }
  int part(const char* name) { return scene().find_part(name); }

  /// The intervals of `unfold` in the latest detection.
  std::size_t intervals_shown() {
    for (const auto& t : studio().collisions()->transitions)
      if (t.transition == unfold_) return t.intervals.size();
    return 0;
  }

  std::unique_ptr<HeadlessFrontend> frontend_;
  int unfold_ = -1;
};

}  // namespace reconfig::studio
