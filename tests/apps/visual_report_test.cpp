// `reconfig check --views` and `--report DIR/`, `reconfig render --interval K --best-view`; the
// visual report opened in headless Chromium (Debian's `chromium`) at a phone's width: every
// image loads and nothing is wider than the screen. Without Chromium those checks are skipped.

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "support/run_command.h"
#include "support/test_data.h"

namespace reconfig {
namespace {

namespace fs = std::filesystem;
using testing::run_reconfig;

constexpr const char* kChromium = "/usr/bin/chromium";

std::string example(const std::string& name) { return (testing::source_dir() / "examples" / name / "scene.json").string(); }

Eigen::Vector3d vec(const nlohmann::json& xyz) { return {xyz[0].get<double>(), xyz[1].get<double>(), xyz[2].get<double>()}; }

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CheckViewsCli, GivesEveryIntervalACameraLookingAtItsBox) {
  const auto run = run_reconfig("check " + example("bench-table") + " --views --json");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const nlohmann::json root = nlohmann::json::parse(run.out);
  int intervals = 0;
  for (const auto& transition : root["transitions"])
    for (const auto& ci : transition["intervals"]) {
      ++intervals;
      ASSERT_TRUE(ci.contains("severity_time")) << "--views implies --energy";
      const auto& view = ci["view"];
      const Eigen::Vector3d eye = vec(view["eye"]);
      const Eigen::Vector3d center = vec(view["center"]);
      const Eigen::Vector3d up = vec(view["up"]);
      const Eigen::Vector3d lo = vec(ci["box_min"]);
      const Eigen::Vector3d hi = vec(ci["box_max"]);
      EXPECT_NEAR((center - (lo + hi) / 2).norm(), 0, 1e-9);  // aimed at the box's center
      EXPECT_GT((eye - center).norm(), (hi - lo).norm() / 2);  // from outside its sphere
      EXPECT_NEAR(up.norm(), 1, 1e-9);
      EXPECT_NEAR(up.dot((center - eye).normalized()), 0, 1e-9);
      EXPECT_GE(up.z(), 0);
      EXPECT_GT(view["visible_fraction"].get<double>(), 0);
      EXPECT_LE(view["visible_fraction"].get<double>(), 1);
    }
  EXPECT_GT(intervals, 0);
}

TEST(RenderIntervalCli, DrawsTheIntervalFromItsBestViewAndNamesABadIndex) {
  const fs::path out = testing::fresh_temp_dir() / "best.png";
  const auto run = run_reconfig("render " + example("bench-table") + " --transition unfold --interval 0 --best-view "
                                "--size 200x150 -o " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("interval 0 at its severity time, best view"), std::string::npos) << run.out;
  EXPECT_GT(fs::file_size(out), 1000u);
  const auto bad = run_reconfig("render " + example("bench-table") + " --transition unfold --interval 9 -o " +
                                out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--interval"), std::string::npos) << bad.err;
  EXPECT_EQ(run_reconfig("render " + example("bench-table") + " --transition unfold --best-view -o " + out.string())
                .exit_code,
            2);  // --best-view needs --interval
}

/// Opens `page` in headless Chromium inside a 390 px wide frame and reports its images and
/// the elements that reach beyond the frame's width, as "images=N broken=K overflowing=M".
std::string probe_in_chromium(const fs::path& folder, const std::string& page) {
  const fs::path probe = folder / "probe.html";
  std::ofstream(probe) << R"(<!doctype html><html><body style="margin:0">
<iframe id="f" src=")" << page << R"(" style="width:390px;height:844px;border:0"></iframe>
<script>
const frame = document.getElementById('f');
frame.onload = () => {
  const doc = frame.contentDocument, root = doc.documentElement, images = [...doc.images];
  const check = () => {
    if (images.some(i => !i.complete)) { setTimeout(check, 50); return; }
    const broken = images.filter(i => i.naturalWidth === 0).length;
    const wide = [...doc.querySelectorAll('body *')].filter(e => e.getBoundingClientRect().right > root.clientWidth + 0.5);
    document.body.setAttribute('data-result', `images=${images.length} broken=${broken} overflowing=${wide.length}`);
  };
  check();
};
</script></body></html>)";
  const fs::path dom = folder / "dom.html";
  const std::string command = std::string(kChromium) +
                              " --headless --no-sandbox --disable-gpu --allow-file-access-from-files"
                              " --virtual-time-budget=20000 --user-data-dir=" + (folder / "chromium").string() +
                              " --dump-dom file://" + probe.string() + " >" + dom.string() + " 2>/dev/null";
  if (std::system(command.c_str()) != 0) return "chromium failed";
  const std::string out = read_text(dom);
  std::smatch match;
  if (!std::regex_search(out, match, std::regex("data-result=\"([^\"]*)\""))) return "no result: " + out;
  return match[1];
}

TEST(VisualReport, IsOnePageWithAPictureOfEveryIntervalThatFitsAPhone) {
  const fs::path folder = testing::fresh_temp_dir();
  const auto run = run_reconfig("check " + example("kitchen") + " --report " + (folder / "report").string() + "/");
  ASSERT_EQ(run.exit_code, 1) << run.err;
  const std::string html = read_text(folder / "report" / "index.html");
  ASSERT_FALSE(html.empty());
  EXPECT_TRUE(fs::exists(folder / "report" / "report.md"));
  EXPECT_EQ(html.find("<script"), std::string::npos);  // self-contained: nothing runs, nothing is fetched
  EXPECT_EQ(html.find("http"), std::string::npos);
  int pictures = 0;
  const std::regex source("src=\"([^\"]+)\"");
  for (std::sregex_iterator it(html.begin(), html.end(), source), end; it != end; ++it) {
    EXPECT_TRUE(fs::exists(folder / "report" / (*it)[1].str())) << (*it)[1];
    pictures += (*it)[1].str().ends_with(".png");
  }
  EXPECT_EQ(pictures, 4);  // the kitchen's four intervals
  for (const char* part : {"cabinet_door_left", "pullout_bin", "table_bracket", "stool_right"})
    EXPECT_NE(html.find(part), std::string::npos) << part;

  if (!fs::exists(kChromium)) GTEST_SKIP() << "no " << kChromium << " (apt-get install chromium): page not opened";
  EXPECT_EQ(probe_in_chromium(folder, "report/index.html"), "images=8 broken=0 overflowing=0");
  // The probe does see a missing picture.
  fs::remove(folder / "report" / "transition-1-interval-1.png");
  EXPECT_EQ(probe_in_chromium(folder, "report/index.html"), "images=8 broken=1 overflowing=0");
}

}  // namespace
}  // namespace reconfig
