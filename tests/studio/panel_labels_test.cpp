// Labels stay readable: the state graph's edges are not drawn through the transitions' names,
// and the timeline's label column fits "move  <part>" of the design's longest part name.

#include <gtest/gtest.h>

#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

class PanelLabels : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(studio().open(bench_table_copy())) << studio().status();
    frontend_.run_frame();
    studio().open_transition(studio().document()->scene().find_transition("unfold"));
    frontend_.run_frame();
    frontend_.run_frame();
  }
  Studio& studio() { return frontend_.studio(); }
  HeadlessFrontend frontend_{1280, 800};
};

TEST_F(PanelLabels, NoEdgeIsDrawnThroughATransitionsName) {
  // The open transition's edge is blue and runs straight through its badge, where its name
  // is written next to it.
  const int unfold = studio().document()->scene().find_transition("unfold");
  const ImVec2 badge = *studio().graph_edge_point(unfold);
  const ImVec2 size = ImGui::CalcTextSize("unfold");
  const render::Image image = frontend_.screenshot();
  int blue = 0;
  for (int y = static_cast<int>(badge.y - size.y / 2); y < static_cast<int>(badge.y + size.y / 2); ++y)
    for (int x = static_cast<int>(badge.x + 14); x < static_cast<int>(badge.x + 14 + size.x); ++x)
      blue += color_distance(image.pixel(x, y), {30, 90, 220, 255}) < 60;
  EXPECT_EQ(blue, 0) << "pixels of the edge's blue within the name";
}

TEST_F(PanelLabels, TheTimelinesLabelColumnFitsTheLongestPartName) {
  const Layout& layout = studio().layout();
  const float column = layout.scrub_min.x - layout.viewport_min.x;  // the timeline starts where the viewport does
  EXPECT_GE(column, ImGui::CalcTextSize("move  armrest_right").x) << column;
}

}  // namespace
}  // namespace reconfig::studio
