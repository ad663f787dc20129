// Fuzzing the linkage loader and the analysis behind it: any mutation of a valid file either
// loads or fails with an InputError; nothing crashes, hangs or throws anything else.

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "linkage_test_util.h"
#include "reconfig/common/input_error.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {
namespace {

std::string file_text(const std::string& name) {
  std::ifstream in(testing::source_dir() / "examples" / "linkages" / name);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string mutate(std::string text, std::mt19937& rng) {
  static const std::string kAlphabet = "{}[]\",:0123456789.-eE truefalsnABCDOPQ";
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits && !text.empty(); ++e) {
    const std::size_t at = rng() % text.size();
    switch (rng() % 5) {
      case 0: text[at] = kAlphabet[rng() % kAlphabet.size()]; break;
      case 1: text.erase(at, 1 + rng() % 8); break;
      case 2: text.insert(at, 1, kAlphabet[rng() % kAlphabet.size()]); break;
      case 3: {  // duplicate a slice (repeats joints, links, names)
        const std::size_t length = std::min<std::size_t>(text.size() - at, 1 + rng() % 60);
        text.insert(rng() % text.size(), text.substr(at, length));
        break;
      }
      case 4: text.insert(at, 1 + rng() % 100'000, "[{"[rng() % 2]); break;  // deep nesting
    }
  }
  return text;
}

TEST(LinkageFuzz, MutatedFilesLoadOrFailCleanly) {
  std::mt19937 rng(2024);
  int loaded = 0, rejected = 0;
  for (const char* name : {"four_bar_crank_rocker.json", "jansen.json", "peaucellier_lipkin.json"}) {
    const std::string original = file_text(name);
    for (int trial = 0; trial < 700; ++trial) {
      const std::string text = mutate(original, rng);
      try {
        const Linkage linkage = parse_linkage(text, "fuzz.json");
        const SymbolicKinematics kinematics(linkage, order_joints(linkage));
        const MotionRange range = motion_range(kinematics, 0.05);
        Eigen::Matrix2Xd X;
        kinematics.solve(0.5 * (range.lower + range.upper), X);
        ++loaded;
      } catch (const InputError&) {
        ++rejected;
      } catch (const std::exception& error) {
        ADD_FAILURE() << "unexpected " << error.what() << " for\n" << text;
      }
    }
  }
  EXPECT_GT(loaded, 50);  // the mutations also produce valid (different) linkages
  EXPECT_GT(rejected, 500);
}

}  // namespace
}  // namespace reconfig::linkage
