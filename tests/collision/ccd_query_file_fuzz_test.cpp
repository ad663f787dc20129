// Fuzzing the CCD query loader: mutated versions of valid query files must either parse into
// well-formed queries or throw InputError naming the file; never crash or throw anything else.
// The default run takes well under a second. For a longer campaign:
//   RECONFIG_FUZZ_TRIALS=100000 RECONFIG_FUZZ_SEED=7 collision_tests --gtest_filter='CcdQueryFileFuzz.*'

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "reconfig/collision/ccd_query_file.h"
#include "reconfig/common/input_error.h"
#include "support/text_mutation.h"

namespace reconfig::collision {
namespace {

constexpr const char* kFileName = "fuzzed.csv";

/// Two valid files: small rationals with signs, blank lines and spaces; and big integers
/// (a numerator near the 2^1000 limit, fractions that are not doubles).
std::vector<std::string> seeds() {
  std::string small, big;
  for (int row = 0; row < 16; ++row) {
    small += std::to_string(row - 7) + ",1, " + std::to_string(2 * row) + ",3,-" + std::to_string(row) + ",+7," +
             std::to_string(row % 2) + "\n";
    if (row == 5) small += "\n   \n";
  }
  const std::string huge = "1" + std::string(290, '0');  // 10^290 < 2^1000
  for (int row = 0; row < 8; ++row)
    big += (row == 2 ? huge : std::to_string(row)) + "," + (row == 2 ? "1" + std::string(280, '0') : "1") +
           ",-123456789012345678901234567890,10000000000000000000000000001,1,3,1\r\n";
  return {small, big};
}

std::string mutate(const std::string& original, std::mt19937& rng) {
  static const std::vector<std::string> tokens = {
      ",",  "\n", "-",   "+", "0",    " ",   "9999999999999999999999999999999", std::string(320, '9'),
      "1e5", ".", "nan", "x", "\r\n", "--1", ",,",                              std::string(1, '\0')};
  return testing::mutate_text(original, rng, tokens, 200);
}

TEST(CcdQueryFileFuzz, MutatedFilesParseOrFailWithAnInputError) {
  const std::vector<std::string> originals = seeds();
  for (const std::string& original : originals) {  // the seeds themselves are valid
    std::istringstream in(original);
    ASSERT_NO_THROW(parse_ccd_queries(in, kFileName));
  }
  std::mt19937 rng(static_cast<unsigned>(testing::fuzz_setting("RECONFIG_FUZZ_SEED", 2024)));
  const int trials = testing::fuzz_setting("RECONFIG_FUZZ_TRIALS", 3000);
  int parsed = 0, refused = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const std::string text = mutate(originals[trial % originals.size()], rng);
    std::istringstream in(text);
    try {
      const std::vector<CcdQuery> queries = parse_ccd_queries(in, kFileName);
      ++parsed;
      for (const CcdQuery& query : queries) {
        for (const Eigen::Vector3d& p : query.points)
          ASSERT_TRUE(p.allFinite() && p.cwiseAbs().maxCoeff() < 0x1p1000) << "trial " << trial;
        ASSERT_TRUE(std::isfinite(query.conversion_error) && query.conversion_error >= 0) << "trial " << trial;
        ASSERT_GE(query.first_line, 1) << "trial " << trial;
      }
    } catch (const InputError& error) {
      ++refused;
      ASSERT_NE(std::string(error.what()).find(kFileName), std::string::npos) << error.what();
      ASSERT_NE(std::string(error.what()).find("line "), std::string::npos) << error.what();
    }
  }
  // Both outcomes are exercised.
  EXPECT_GT(parsed, trials / 50);
  EXPECT_GT(refused, trials / 4);
}

TEST(CcdQueryFileFuzz, CoordinatesBeyondTheDoublesAreRefusedNotUndefined) {
  // 10^400 overflows a double: converting it is undefined (GMP raises SIGFPE), so the range is
  // checked exactly first.
  std::string text = "1" + std::string(400, '0') + ",1,0,1,0,1,1\n";
  for (int row = 1; row < 8; ++row) text += "0,1,0,1,0,1,1\n";
  std::istringstream in(text);
  try {
    parse_ccd_queries(in, kFileName);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("line 1"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("out of range"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace reconfig::collision
