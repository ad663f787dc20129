#include "reconfig/linkage/linkage_svg.h"

#include <gtest/gtest.h>

#include "linkage_test_util.h"

namespace reconfig::linkage {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(LinkageSvg, DrawsCurvesLinksAndJoints) {
  const Linkage linkage = test::example("jansen.json");
  const std::string svg = linkage_svg(linkage, {.samples = 90, .width = 600, .title = "Jansen <leg>"});
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("Jansen &lt;leg&gt;"), std::string::npos);
  EXPECT_NE(svg.find("full rotation"), std::string::npos);
  // One closed curve per moving joint (6), with 90 points each; one bar or polygon per link.
  EXPECT_EQ(count(svg, "<polygon data-joint="), 6);
  EXPECT_EQ(count(svg, "<line "), 5);
  EXPECT_EQ(count(svg, "<polygon points="), 2);
  EXPECT_EQ(count(svg, "<rect x="), 2);  // fixed joints
  const auto foot = svg.find("data-joint=\"P\"");
  ASSERT_NE(foot, std::string::npos);
  const std::string points = svg.substr(foot, svg.find("/>", foot) - foot);
  EXPECT_EQ(count(points, ","), 90);
  EXPECT_NE(points.find("stroke-width=\"2\""), std::string::npos);  // a tracking point
}

TEST(LinkageSvg, ARockerShowsItsRange) {
  const std::string svg = linkage_svg(test::example("peaucellier_lipkin.json"));
  EXPECT_NE(svg.find("rocks between -82.8° and 82.8°"), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline data-joint="), 4);
}

}  // namespace
}  // namespace reconfig::linkage
