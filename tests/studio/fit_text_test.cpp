// Labels fit their place: cut to a width with "..." (the timeline's row label read
// "move  (no part" and cut part names after 14 characters, whatever their width).

#include <gtest/gtest.h>

#include "fit_text.h"
#include "frontend.h"

namespace reconfig::studio {
namespace {

class FitText : public ::testing::Test {
 protected:
  void SetUp() override { frontend_.run_frame(); }  // the frame's font
  HeadlessFrontend frontend_{640, 400};
};

TEST_F(FitText, AShortTextStaysWhole) { EXPECT_EQ(fit_text("move  backrest", 200), "move  backrest"); }

TEST_F(FitText, ALongTextIsCutToTheWidthWithDots) {
  const std::string text = "move  cabinet_door_left";
  const float width = ImGui::CalcTextSize("move  cabinet").x + 1;
  const std::string fitted = fit_text(text, width);
  EXPECT_LE(ImGui::CalcTextSize(fitted.c_str()).x, width);
  ASSERT_GE(fitted.size(), 4u);
  EXPECT_EQ(fitted.substr(fitted.size() - 3), "...");
  EXPECT_EQ(text.rfind(fitted.substr(0, fitted.size() - 3), 0), 0u) << fitted;  // a beginning of it
  EXPECT_GT(fitted.size(), 6u) << "as much as fits is kept: " << fitted;
}

TEST_F(FitText, NothingFitsButTheDots) { EXPECT_EQ(fit_text("backrest", 1), "..."); }

}  // namespace
}  // namespace reconfig::studio
