// The inspector's collision intervals: no part name is cut ("cabinet_door_left × pullout_s");
// the names go on lines of their own when the panel is narrow.

#include "interval_label.h"

#include <gtest/gtest.h>

#include <sstream>

#include "frontend.h"

namespace reconfig::studio {
namespace {

class IntervalLabel : public ::testing::Test {
 protected:
  void SetUp() override { frontend_.run_frame(); }  // the frame's font
  HeadlessFrontend frontend_{640, 400};
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST_F(IntervalLabel, NamesThatDoNotFitTogetherGoOnLinesOfTheirOwn) {
  const std::vector<std::string> parts = {"cabinet_door_left", "pullout_shelf"};
  const float width = ImGui::CalcTextSize("cabinet_door_left × pull").x;  // narrower than both
  const std::vector<std::string> lines = lines_of(interval_label(0.023, 0.497, parts, width));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "0.023-0.497");
  EXPECT_EQ(lines[1], "cabinet_door_left");
  EXPECT_EQ(lines[2], "× pullout_shelf");
  for (const std::string& line : lines) EXPECT_LE(ImGui::CalcTextSize(line.c_str()).x, width) << line;
}

TEST_F(IntervalLabel, NamesThatFitShareALine) {
  const std::string label = interval_label(0.117, 0.674, {"backrest", "armrest_left"}, 400);
  EXPECT_EQ(label, "0.117-0.674\nbackrest × armrest_left");
}

TEST_F(IntervalLabel, ANameTooWideForALineAloneIsCutWithDots) {
  const float width = ImGui::CalcTextSize("cabinet_").x;
  const std::vector<std::string> lines = lines_of(interval_label(0, 1, {"cabinet_door_left", "bin"}, width));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1].substr(lines[1].size() - 3), "...");
  EXPECT_LE(ImGui::CalcTextSize(lines[1].c_str()).x, width);
  EXPECT_EQ(lines[2], "× bin");
}

}  // namespace
}  // namespace reconfig::studio
