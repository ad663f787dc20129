// A keyframed track's `"ease"`: translation keys written without handles move eased
// ("smooth", the default: each segment starts and ends at rest) or at constant speed
// ("linear"); written handles are kept; the handles are written back explicitly.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A drawer that slides 0.4 along x over three keys, none with handles.
json drawer_scene() {
  return json::parse(R"({
    "format": "reconfig-scene", "version": 1,
    "parts": [{"name": "drawer", "box": {"size": [0.4, 0.4, 0.2]}}],
    "states": [{"name": "in", "poses": {}}, {"name": "out", "poses": {"drawer": {"translation": [0.4, 0, 0]}}}],
    "transitions": [{"name": "pull", "from": "in", "to": "out", "tracks": {"drawer": {"translation": [
      {"time": 0, "point": [0, 0, 0]}, {"time": 0.5, "point": [0.1, 0, 0]}, {"time": 1, "point": [0.4, 0, 0]}]}}}]})");
}

json with_ease(const char* ease) {
  json document = drawer_scene();
  document["transitions"][0]["tracks"]["drawer"]["ease"] = ease;
  return document;
}

Reconfigurable parse(const json& document) { return parse_scene(document.dump(), fs::current_path(), "drawer.json"); }

double x_at(const Reconfigurable& scene, double t) { return scene.pose_at(0, 0, t).translation.x(); }

TEST(TranslationEase, LinearMovesAtConstantSpeedBetweenKeys) {
  const Reconfigurable scene = parse(with_ease("linear"));
  for (double t : {0.1, 0.25, 0.4}) EXPECT_NEAR(x_at(scene, t), 0.2 * t, 1e-15) << t;              // 0.1 over 0.5
  for (double t : {0.6, 0.75, 0.9}) EXPECT_NEAR(x_at(scene, t), 0.1 + 0.6 * (t - 0.5), 1e-15) << t;  // 0.3 over 0.5
}

TEST(TranslationEase, SmoothIsTheDefaultAndStartsAndEndsEachSegmentAtRest) {
  const Reconfigurable by_default = parse(drawer_scene()), smooth = parse(with_ease("smooth"));
  for (double t : {0.1, 0.25, 0.7}) EXPECT_EQ(x_at(by_default, t), x_at(smooth, t)) << t;
  // (1−f)³·0 + 3(1−f)²f·0 + 3(1−f)f²·0.1 + f³·0.1 at f = 1/2: half way, but slow near the keys.
  EXPECT_NEAR(x_at(smooth, 0.25), 0.05, 1e-15);
  EXPECT_LT(x_at(smooth, 0.05), 0.2 * 0.05 / 2);
}

TEST(TranslationEase, WrittenHandlesAreKept) {
  json document = with_ease("linear");
  document["transitions"][0]["tracks"]["drawer"]["translation"][1]["in"] = {0.1, 0, 0};  // arrive at rest
  const auto& keys = std::get<KeyframedTrack>(parse(document).transitions[0].tracks.at("drawer")).translation;
  EXPECT_EQ(keys[1].in, Eigen::Vector3d(0.1, 0, 0));
  EXPECT_TRUE(keys[1].out.isApprox(Eigen::Vector3d(0.2, 0, 0), 1e-15));  // a third of the way to 0.4
  EXPECT_TRUE(keys[0].out.isApprox(Eigen::Vector3d(0.1 / 3, 0, 0), 1e-15));
  EXPECT_EQ(keys[0].in, Eigen::Vector3d::Zero());  // the ends have no neighbour on that side
  EXPECT_EQ(keys[2].out, Eigen::Vector3d(0.4, 0, 0));
}

TEST(TranslationEase, RoundTripWritesTheHandlesItImplied) {
  const Reconfigurable scene = parse(with_ease("linear"));
  const json saved = json::parse(scene_to_json(scene, fs::current_path()));
  EXPECT_FALSE(saved["transitions"][0]["tracks"]["drawer"].contains("ease"));
  const Reconfigurable again = parse_scene(saved.dump(), fs::current_path(), "again.json");
  for (double t : {0.0, 0.2, 0.5, 0.8, 1.0}) EXPECT_EQ(x_at(again, t), x_at(scene, t)) << t;
}

TEST(TranslationEase, ErrorsNameThePlace) {
  const auto error_of = [](const json& document) {
    try {
      parse(document);
    } catch (const InputError& error) {
      return std::string(error.location()) + ": " + error.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(with_ease("constant")),
            "transitions[0].tracks.drawer.ease: unknown ease \"constant\" (expected \"smooth\" or \"linear\")");
  json screw = drawer_scene();
  screw["transitions"][0]["tracks"]["drawer"] =
      json::parse(R"({"interpolation": "screw", "ease": "linear", "poses": [{"time": 0}]})");
  EXPECT_EQ(error_of(screw).rfind("transitions[0].tracks.drawer.ease: unknown field", 0), 0u) << error_of(screw);
}

}  // namespace
}  // namespace reconfig::scene
