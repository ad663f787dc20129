// The gizmo does not hide the selected part's collision box: while a box of the part is shown,
// its handles are drawn see-through (the picture under them shows), else opaque.

#include <gtest/gtest.h>

#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

using std::chrono::milliseconds;

class GizmoFade : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
    frontend_.run_frame();
    ASSERT_TRUE(frontend_.run_until_collisions_current(milliseconds(60000)));
    studio().open_transition(studio().document()->scene().find_transition("unfold"));
    studio().select_part(studio().document()->scene().find_part("backrest"));
  }
  Studio& studio() { return frontend_.studio(); }

  /// The picture at the middle of the gizmo's x arrow at time t.
  std::array<std::uint8_t, 4> arrow_pixel(double t) {
    studio().set_time(t);
    frontend_.run_frame();
    frontend_.run_frame();
    const auto gizmo = studio().gizmo();
    EXPECT_TRUE(gizmo);
    const auto at = studio().viewport_point(gizmo->center + 0.5 * gizmo->arrow_length * Eigen::Vector3d::UnitX());
    EXPECT_TRUE(at);
    return frontend_.screenshot().pixel(static_cast<int>(at->x), static_cast<int>(at->y));
  }

  HeadlessFrontend frontend_{1000, 700};
};

TEST_F(GizmoFade, TheGizmoIsSeeThroughWhileThePartsBoxIsShown) {
  // The backrest meets the armrests over t = 0.117 – 0.674 of "unfold".
  const auto opaque = arrow_pixel(0.0);
  EXPECT_GT(opaque[0], 200) << "the x arrow is red";
  const auto faded = arrow_pixel(0.4);
  EXPECT_GT(color_distance(faded, opaque), 60) << "drawn see-through over what is behind it";
  studio().show_intervals = false;  // no boxes: nothing to see through to
  EXPECT_LE(color_distance(arrow_pixel(0.4), opaque), 10);
}

}  // namespace
}  // namespace reconfig::studio
