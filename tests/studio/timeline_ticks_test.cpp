// The time strip's last tick label, "1.0", is drawn inside the strip, left of its tick: drawn
// right of it like the others, it ran past the strip and was cut to "1.".

#include <gtest/gtest.h>

#include "studio_test_util.h"

namespace reconfig::studio {
namespace {

/// Pixels of the tick labels' grey in columns [x0, x1) of the strip's rows.
int label_pixels(const render::Image& image, const Layout& layout, int x0, int x1) {
  int count = 0;
  for (int y = static_cast<int>(layout.scrub_min.y); y < static_cast<int>(layout.scrub_max.y); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x)
      count += color_distance(image.pixel(x, y), {110, 110, 120, 255}) < 60;
  return count;
}

TEST(TimelineTicks, TheLastLabelIsInsideTheStrip) {
  HeadlessFrontend frontend(1000, 700);
  ASSERT_TRUE(frontend.studio().open(bench_table_copy())) << frontend.studio().status();
  frontend.run_frame();
  frontend.run_frame();
  const Layout& layout = frontend.studio().layout();
  const render::Image image = frontend.screenshot();
  const int end = static_cast<int>(layout.scrub_max.x);
  EXPECT_GT(label_pixels(image, layout, end - 30, end - 1), 10) << "\"1.0\" left of the last tick";
  EXPECT_EQ(label_pixels(image, layout, end + 1, end + 30), 0) << "nothing of it beyond the strip";
}

}  // namespace
}  // namespace reconfig::studio
