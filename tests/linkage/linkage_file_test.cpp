#include "reconfig/linkage/linkage_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "reconfig/common/input_error.h"
#include "linkage_test_util.h"
#include "support/test_data.h"

namespace reconfig::linkage {
namespace {

const char* kFourBar = R"({
  "format": "reconfig-linkage", "version": 1,
  "joints": [
    {"name": "A", "position": [0, 0], "fixed": true},
    {"name": "B", "position": [1, 0]},
    {"name": "C", "position": [3, 3]},
    {"name": "D", "position": [4, 0], "fixed": true}
  ],
  "links": [["A", "B"], ["B", "C"], ["D", "C"]],
  "motor": {"center": "A", "joint": "B"},
  "tracking_points": [{"name": "tip", "joint": "C"}]
})";

// Replaces the first occurrence of `from` in kFourBar by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string text = kFourBar;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The location and message of the InputError parsing `text` throws.
std::pair<std::string, std::string> error_of(const std::string& text) {
  try {
    parse_linkage(text, "f.json");
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "f.json");
    return {error.location(), error.message()};
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

TEST(LinkageFile, ParsesTheModel) {
  const Linkage linkage = parse_linkage(kFourBar);
  ASSERT_EQ(linkage.joints.size(), 4u);
  EXPECT_EQ(linkage.joints[2].name, "C");
  EXPECT_EQ(linkage.joints[2].position, Eigen::Vector2d(3, 3));
  EXPECT_TRUE(linkage.joints[0].fixed);
  EXPECT_FALSE(linkage.joints[1].fixed);
  EXPECT_EQ(linkage.links, (std::vector<std::vector<int>>{{0, 1}, {1, 2}, {3, 2}}));
  EXPECT_EQ(linkage.motor.center, 0);
  EXPECT_EQ(linkage.motor.joint, 1);
  ASSERT_EQ(linkage.tracking_points.size(), 1u);
  EXPECT_EQ(linkage.tracking_points[0].joint, 2);
}

TEST(LinkageFile, RoundTripsExactly) {
  Linkage linkage = parse_linkage(kFourBar);
  linkage.joints[2].position = {0.1 + 0.2, 1.0 / 3.0};
  const Linkage again = parse_linkage(linkage_to_json(linkage));
  EXPECT_EQ(again.joints[2].position, linkage.joints[2].position);
  EXPECT_EQ(linkage_to_json(again), linkage_to_json(linkage));
}

TEST(LinkageFile, EveryErrorNamesItsPlace) {
  using Expect = std::pair<std::string, std::string>;
  const std::vector<std::pair<std::string, Expect>> cases = {
      {"{", {"", "malformed JSON"}},
      {"[1]", {"", "expected a JSON object"}},
      {with("\"reconfig-linkage\"", "\"other\""), {"format", "expected \"reconfig-linkage\""}},
      {with("\"version\": 1", "\"version\": 2"), {"version", "unsupported version"}},
      {with("\"version\": 1", "\"version\": 4294967297"), {"version", "unsupported version: the number 4294967297"}},
      {with("\"version\": 1", "\"version\": 1, \"version\": 1"), {"version", "duplicate key"}},
      {with("\"name\": \"B\"", "\"name\": \"B\\u001b[2J\""), {"joints[1].name", "control characters"}},
      {with("\"version\": 1", "\"version\": 1, \"x\": " + std::string(200, '[') + std::string(200, ']')),
       {"x" + [] { std::string p; for (int i = 0; i < 99; ++i) p += "[0]"; return p; }(), "nested deeper than 100"}},
      {with("\"joints\": [", "\"joints_\": ["), {"", "missing \"joints\""}},
      {with("\"name\": \"B\"", "\"name\": \"A\""), {"joints[1].name", "duplicate joint name \"A\""}},
      {with("\"name\": \"B\"", "\"name\": \"\""), {"joints[1].name", "empty joint name"}},
      {with("[1, 0]", "[1]"), {"joints[1].position", "expected a point [x, y]"}},
      {with("[1, 0]", "[1, \"x\"]"), {"joints[1].position[1]", "expected a number"}},
      {with("[1, 0]", "[1e300, 0]"), {"joints[1].position[0]", "out of range"}},
      {with("[1, 0]", "[1, 1e999]"), {"", "malformed JSON"}},
      {with("\"fixed\": true", "\"fixed\": 1"), {"joints[0].fixed", "expected true or false"}},
      {with("[\"B\", \"C\"]", "[\"B\"]"), {"links[1]", "two or more joints"}},
      {with("[\"B\", \"C\"]", "[\"B\", \"Q\"]"), {"links[1][1]", "unknown joint \"Q\""}},
      {with("[\"B\", \"C\"]", "[\"B\", \"B\"]"), {"links[1][1]", "appears twice"}},
      {with("[3, 3]", "[1, 0]"), {"links[1][1]", "same position"}},
      {with("[[\"A\", \"B\"], [\"B\", \"C\"], [\"D\", \"C\"]]", "[[\"A\", \"B\"], [\"D\", \"B\"]]"),
       {"joints[2]", "\"C\" is on no link"}},
      {with("\"center\": \"A\"", "\"center\": \"C\""), {"motor.center", "must be a fixed joint"}},
      {with("\"joint\": \"B\"", "\"joint\": \"D\""), {"motor.joint", "must not be fixed"}},
      {with("\"joint\": \"B\"", "\"joint\": \"A\""), {"motor.joint", "must differ"}},
      {with("\"joint\": \"B\"", "\"joint\": \"C\""), {"motor", "no link (crank)"}},
      {with("\"motor\"", "\"motor_\""), {"", "missing \"motor\""}},
      {with("\"joint\": \"C\"}]", "\"joint\": \"Z\"}]"), {"tracking_points[0].joint", "unknown joint \"Z\""}},
  };
  for (const auto& [text, expected] : cases) {
    const auto [location, message] = error_of(text);
    EXPECT_EQ(location, expected.first) << text;
    EXPECT_NE(message.find(expected.second), std::string::npos) << message << "\n" << text;
  }
}

TEST(LinkageFile, ReadRejectsUnderConstrainedAndSingularLinkages) {
  const auto dir = testing::fresh_temp_dir();
  // A dangling chain: C hangs from B by one link only.
  const std::string under = with("[[\"A\", \"B\"], [\"B\", \"C\"], [\"D\", \"C\"]]", "[[\"A\", \"B\"], [\"B\", \"C\"]]");
  const auto under_path = dir / "under.json";
  { std::ofstream(under_path) << under; }
  try {
    read_linkage(under_path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), under_path.string());
    EXPECT_NE(error.message().find("\"C\" is not determined"), std::string::npos) << error.what();
  }
  // Collinear A-B-C-D four-bar in the initial configuration: triangle (B, D) -> C is flat.
  const std::string flat = with("[3, 3]", "[2.5, 0]");
  const auto flat_path = dir / "flat.json";
  { std::ofstream(flat_path) << flat; }
  try {
    read_linkage(flat_path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("singular in the initial configuration"), std::string::npos) << error.what();
    EXPECT_EQ(error.location(), "joints[2]");
  }
  // An extra bar B–D locks the four-bar: |BD| changes as the crank turns.
  const std::string locked = with("[\"D\", \"C\"]]", "[\"D\", \"C\"], [\"B\", \"D\"]]");
  const auto locked_path = dir / "locked.json";
  { std::ofstream(locked_path) << locked; }
  try {
    read_linkage(locked_path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "links[3]");
    EXPECT_NE(error.message().find("over-constrained"), std::string::npos) << error.what();
  }
  // The crank pin on a link with both fixed joints: it cannot turn.
  const std::string grounded = with("[[\"A\", \"B\"],", "[[\"A\", \"B\", \"D\"],");
  const auto grounded_path = dir / "grounded.json";
  { std::ofstream(grounded_path) << grounded; }
  try {
    read_linkage(grounded_path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "links[0]");
    EXPECT_NE(error.message().find("over-constrained"), std::string::npos) << error.what();
  }
    // A redundant but consistent bar (parallel to the crank of a parallelogram) is accepted.
  const std::string parallelogram = R"({"format": "reconfig-linkage", "version": 1,
    "joints": [{"name": "A", "position": [0, 0], "fixed": true}, {"name": "D", "position": [4, 0], "fixed": true},
               {"name": "E", "position": [2, 0], "fixed": true},
               {"name": "B", "position": [0, 1]}, {"name": "C", "position": [4, 1]}, {"name": "F", "position": [2, 1]}],
    "links": [["A", "B"], ["B", "F", "C"], ["D", "C"], ["E", "F"]], "motor": {"center": "A", "joint": "B"}})";
  const auto parallelogram_path = dir / "parallelogram.json";
  { std::ofstream(parallelogram_path) << parallelogram; }
  EXPECT_NO_THROW(read_linkage(parallelogram_path));
  EXPECT_THROW(read_linkage(dir / "missing.json"), InputError);
  EXPECT_THROW(write_linkage(parse_linkage(kFourBar), dir / "no-such-dir" / "out.json"), InputError);
}

TEST(LinkageFile, AllExamplesLoad) {
  for (const char* name : test::kExamples) {
    EXPECT_NO_THROW(read_linkage(testing::source_dir() / "examples" / "linkages" / name)) << name;
  }
}

}  // namespace
}  // namespace reconfig::linkage
