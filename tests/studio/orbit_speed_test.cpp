// Orbiting the viewport turns the view 30° per 100 pixels of drag, as Blender does: slow
// enough for fine work (it was 46°).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "script.h"
#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

TEST(OrbitSpeed, ADragOfOneHundredPixelsTurnsTheViewThirtyDegrees) {
  HeadlessFrontend frontend(1000, 700);
  Studio& studio = frontend.studio();
  ASSERT_TRUE(studio.open(bench_table_copy())) << studio.status();
  frontend.run_frame();
  const Layout& layout = studio.layout();
  const int x = static_cast<int>((layout.viewport_min.x + layout.viewport_max.x) / 2);
  const int y = static_cast<int>((layout.viewport_min.y + layout.viewport_max.y) / 2);
  const double yaw = studio.camera().yaw, pitch = studio.camera().pitch;
  run_script(frontend, "drag " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(x + 100) + " " +
                           std::to_string(y) + "\n", "orbit.txt");
  EXPECT_NEAR((yaw - studio.camera().yaw) * 180 / std::numbers::pi, 30.0, 1e-9);
  EXPECT_EQ(studio.camera().pitch, pitch);
  EXPECT_EQ(studio.selected_part(), -1) << "a drag is not a click";
}

}  // namespace
}  // namespace reconfig::studio
