#include "reconfig/scene/scene_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <nlohmann/json.hpp>

#include "reconfig/common/input_error.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/geometry/primitives.h"
#include "support/test_data.h"

namespace reconfig::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A small valid scene: a box that slides and turns, a sphere that stays.
json valid_scene() {
  return json::parse(R"({
    "format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [
      {"name": "lid", "box": {"size": [1, 0.5, 0.1]}, "color": [0.8, 0.6, 0.4]},
      {"name": "ball", "sphere": {"radius": 0.2}}
    ],
    "states": [
      {"name": "closed", "poses": {"lid": {"translation": [0, 0, 0.45], "rotation": [1, 0, 0, 0]}}},
      {"name": "open", "poses": {"lid": {"translation": [0, 0.2, 0.75], "rotation": [0.7071, 0.7071, 0, 0]}}}
    ],
    "transitions": [
      {"name": "unfold", "from": "closed", "to": "open",
       "tracks": {"lid": {
         "translation": [
           {"time": 0.0, "point": [0, 0, 0.45], "in": [0, 0, 0.45], "out": [0, 0.1, 0.6]},
           {"time": 1.0, "point": [0, 0.2, 0.75], "in": [0, 0.2, 0.6], "out": [0, 0.2, 0.75]}],
         "rotation": [
           {"time": 0.0, "quaternion": [1, 0, 0, 0]},
           {"time": 0.5, "quaternion": [0.9239, 0.3827, 0, 0]},
           {"time": 1.0, "quaternion": [0.7071, 0.7071, 0, 0]}]}}}
    ]})");
}

/// `document` with collision settings of its own.
json with_collision_settings(json document) {
  document["collision"] = {
      {"tolerance", 0.0005}, {"dop", 80}, {"box_resolution", 0}, {"frame", 0.04}, {"conservative", true},
      {"clearance", 0.002}};
  return document;
}

Reconfigurable parse(const json& document) { return parse_scene(document.dump(), fs::current_path(), "test.json"); }

/// Parses `document` and returns the error's location, failing if it parses.
InputError parse_error(const json& document) {
  try {
    parse(document);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "expected an InputError for " << document.dump();
  return InputError("", "", "");
}

TEST(SceneFile, ParsesTheFormatsExample) {
  const Reconfigurable scene = parse(valid_scene());
  ASSERT_EQ(scene.parts.size(), 2u);
  EXPECT_EQ(scene.parts[0].name, "lid");
  EXPECT_EQ(scene.parts[0].mesh.face_count(), 12);
  EXPECT_TRUE(scene.parts[0].center.isZero(1e-12));
  EXPECT_EQ(scene.states.size(), 2u);
  ASSERT_EQ(scene.transitions.size(), 1u);
  EXPECT_TRUE(scene.transitions[0].bidirectional);
  // The motion interpolates the state poses at both ends.
  EXPECT_TRUE(scene.pose_at(0, 0, 0.0).translation.isApprox(Eigen::Vector3d(0, 0, 0.45)));
  EXPECT_TRUE(scene.pose_at(0, 0, 1.0).translation.isApprox(Eigen::Vector3d(0, 0.2, 0.75)));
  // The ball has no track: it holds its (identity) pose.
  EXPECT_TRUE(scene.pose_at(0, 1, 0.3).translation.isZero());
}

TEST(SceneFile, RoundTripIsLossless) {
  const Reconfigurable scene = parse(valid_scene());
  const std::string once = scene_to_json(scene, fs::current_path());
  const Reconfigurable again = parse_scene(once, fs::current_path(), "again.json");
  EXPECT_EQ(scene_to_json(again, fs::current_path()), once);
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const motion::Pose a = scene.pose_at(0, 0, t), b = again.pose_at(0, 0, t);
    EXPECT_EQ(a.translation, b.translation) << t;
    EXPECT_EQ(a.rotation.coeffs(), b.rotation.coeffs()) << t;
  }
}

TEST(SceneFile, CollisionSettingsRoundTrip) {
  const Reconfigurable scene = parse(with_collision_settings(valid_scene()));
  const CollisionSettings expected{
      .tolerance = 0.0005, .dop = 80, .box_resolution = 0.0, .frame = 0.04, .conservative = true, .clearance = 0.002};
  EXPECT_EQ(scene.collision, expected);
  const Reconfigurable again = parse_scene(scene_to_json(scene, fs::current_path()), fs::current_path(), "again.json");
  EXPECT_EQ(again.collision, expected);

  // Only the settings a design gives are written back; none, no "collision" object at all.
  json partial = valid_scene();
  partial["collision"] = {{"dop", 8}};
  const Reconfigurable some = parse(partial);
  EXPECT_EQ(some.collision, CollisionSettings{.dop = 8});
  EXPECT_EQ(json::parse(scene_to_json(some, fs::current_path()))["collision"], partial["collision"]);
  EXPECT_FALSE(json::parse(scene_to_json(parse(valid_scene()), fs::current_path())).contains("collision"));
}

TEST(SceneFile, SavedViewRoundTrips) {
  json document = valid_scene();
  document["view"] = {{"target", {0.5, -1, 0.25}}, {"distance", 3.5}, {"yaw_degrees", 60}, {"pitch_degrees", -20}};
  const Reconfigurable scene = parse(document);
  ASSERT_TRUE(scene.view);
  EXPECT_EQ(*scene.view, (SavedView{Eigen::Vector3d(0.5, -1, 0.25), 3.5, 60, -20}));
  EXPECT_EQ(json::parse(scene_to_json(scene, fs::current_path()))["view"], document["view"]);
  // None given, none written.
  EXPECT_FALSE(parse(valid_scene()).view);
  EXPECT_FALSE(json::parse(scene_to_json(parse(valid_scene()), fs::current_path())).contains("view"));
}

TEST(SceneFile, GroundIsOnUnlessTheFileSaysFloating) {
  EXPECT_TRUE(parse(valid_scene()).ground);
  EXPECT_FALSE(json::parse(scene_to_json(parse(valid_scene()), fs::current_path())).contains("ground"));
  json floating = valid_scene();
  floating["ground"] = false;
  const Reconfigurable scene = parse(floating);
  EXPECT_FALSE(scene.ground);
  EXPECT_EQ(json::parse(scene_to_json(scene, fs::current_path()))["ground"], false);
  floating["ground"] = "no";
  EXPECT_THROW(parse(floating), InputError);
}

TEST(SceneFile, SaveWritesAtomicallyAndKeepsMeshPathsRelative) {
  const fs::path dir = testing::fresh_temp_dir();
  fs::create_directories(dir / "meshes");
  geometry::save_obj(dir / "meshes" / "block.obj", geometry::make_box({0.2, 0.3, 0.4}));
  json document = valid_scene();
  document["parts"].push_back({{"name", "block"}, {"mesh", "meshes/block.obj"}});
  {
    std::ofstream(dir / "scene.json") << document.dump(2);
  }
  Reconfigurable scene = load_scene(dir / "scene.json");
  ASSERT_EQ(scene.parts.size(), 3u);
  EXPECT_EQ(scene.parts[2].mesh.face_count(), 12);

  const fs::path moved = dir / "copy" / "moved.json";
  fs::create_directories(moved.parent_path());
  save_scene(scene, moved);
  EXPECT_FALSE(fs::exists(moved.string() + ".tmp"));
  const json saved = json::parse(std::ifstream(moved));
  EXPECT_EQ(saved["parts"][2]["mesh"], "../meshes/block.obj");
  // A mesh outside the scene's folder is read only when the user allows it.
  EXPECT_THROW(load_scene(moved), InputError);
  EXPECT_EQ(load_scene(moved, {.allow_outside_paths = true}).parts[2].mesh.face_count(), 12);
}

TEST(SceneFile, ScrewTracksRoundTrip) {
  json document = valid_scene();
  document["transitions"][0]["tracks"]["lid"] = json::parse(R"({"interpolation": "screw", "poses": [
      {"time": 0, "translation": [0, 0, 0.45], "rotation": [1, 0, 0, 0]},
      {"time": 1, "translation": [0, 0.2, 0.75], "rotation": [0.7071, 0.7071, 0, 0]}]})");
  const Reconfigurable scene = parse(document);
  ASSERT_TRUE(std::holds_alternative<ScrewPosesTrack>(scene.transitions[0].tracks.at("lid")));
  const Reconfigurable again = parse_scene(scene_to_json(scene, fs::current_path()), fs::current_path(), "x");
  EXPECT_TRUE(scene.pose_at(0, 0, 0.4).translation.isApprox(again.pose_at(0, 0, 0.4).translation));
}

struct BadInput {
  std::string what;
  std::function<void(json&)> mutate;
  std::string location;        ///< expected JSON path
  std::string message_part;    ///< expected substring of the message
};

class SceneFileErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(SceneFileErrors, NameThePlace) {
  json document = valid_scene();
  GetParam().mutate(document);
  const InputError error = parse_error(document);
  EXPECT_EQ(error.file(), "test.json");
  EXPECT_EQ(error.location(), GetParam().location) << error.what();
  EXPECT_NE(error.message().find(GetParam().message_part), std::string::npos) << error.what();
}

const json kNaN = std::numeric_limits<double>::quiet_NaN();  // serialized as null by nlohmann

INSTANTIATE_TEST_SUITE_P(
    Scene, SceneFileErrors,
    ::testing::Values(
        BadInput{"wrong format", [](json& d) { d["format"] = "other"; }, "format", "reconfig-scene"},
        BadInput{"future version", [](json& d) { d["version"] = 2; }, "version", "unsupported version"},
        BadInput{"unknown field", [](json& d) { d["parts"][0]["colour"] = 1; }, "parts[0].colour", "unknown field"},
        BadInput{"unknown part in state", [](json& d) { d["states"][0]["poses"]["lidd"] = json::object(); },
                 "states[0].poses.lidd", "unknown part"},
        BadInput{"unknown part in track",
                 [](json& d) { d["transitions"][0]["tracks"]["nope"] = d["transitions"][0]["tracks"]["lid"]; },
                 "transitions[0].tracks.nope", "unknown part"},
        BadInput{"unknown state", [](json& d) { d["transitions"][0]["to"] = "opened"; }, "transitions[0].to",
                 "unknown state"},
        BadInput{"NaN coordinate", [](json& d) { d["states"][1]["poses"]["lid"]["translation"][1] = kNaN; },
                 "states[1].poses.lid.translation[1]", "expected a number"},
        BadInput{"non-unit quaternion",
                 [](json& d) { d["transitions"][0]["tracks"]["lid"]["rotation"][1]["quaternion"] = {1, 1, 0, 0}; },
                 "transitions[0].tracks.lid.rotation[1].quaternion", "unit length"},
        BadInput{"times out of order",
                 [](json& d) { d["transitions"][0]["tracks"]["lid"]["rotation"][1]["time"] = 0.0; },
                 "transitions[0].tracks.lid.rotation[1].time", "strictly increase"},
        BadInput{"time outside [0, 1]",
                 [](json& d) { d["transitions"][0]["tracks"]["lid"]["rotation"][2]["time"] = 1.5; },
                 "transitions[0].tracks.lid.rotation[2].time", "[0, 1]"},
        BadInput{"end key disagrees with its state",
                 [](json& d) { d["transitions"][0]["tracks"]["lid"]["translation"][1]["point"] = {0, 0.3, 0.75}; },
                 "transitions[0].tracks.lid.translation[1].point", "state \"open\""},
        BadInput{"first rotation key disagrees",
                 [](json& d) {
                   d["transitions"][0]["tracks"]["lid"]["rotation"][0]["quaternion"] = {0.7071, 0.7071, 0, 0};
                 },
                 "transitions[0].tracks.lid.rotation[0]", "state \"closed\""},
        BadInput{"part without track moves",
                 [](json& d) { d["states"][1]["poses"]["ball"] = {{"translation", {1, 0, 0}}}; },
                 "transitions[0].tracks", "has no track"},
        BadInput{"duplicate part name", [](json& d) { d["parts"][1]["name"] = "lid"; }, "parts[1].name", "duplicate"},
        BadInput{"two geometry sources",
                 [](json& d) { d["parts"][1]["box"] = {{"size", {1, 1, 1}}}; }, "parts[1]", "exactly one"},
        BadInput{"negative box size", [](json& d) { d["parts"][0]["box"]["size"][2] = -1; }, "parts[0].box.size[2]",
                 "positive"},
        BadInput{"missing mesh file", [](json& d) { d["parts"][1] = {{"name", "x"}, {"mesh", "missing.obj"}}; },
                 "parts[1].mesh", "missing.obj"},
        BadInput{"missing required field", [](json& d) { d["transitions"][0].erase("from"); },
                 "transitions[0].from", "missing required field"},
        BadInput{"wrong type", [](json& d) { d["parts"] = "lid"; }, "parts", "expected an array"},
        BadInput{"misspelled collision setting", [](json& d) { d["collision"] = {{"tolerence", 0.001}}; },
                 "collision.tolerence", "unknown field"},
        BadInput{"zero tolerance", [](json& d) { d["collision"] = {{"tolerance", 0}}; }, "collision.tolerance",
                 "positive distance"},
        BadInput{"unknown k-DOP family", [](json& d) { d["collision"] = {{"dop", 26}}; }, "collision.dop", "8, 28 or 80"},
        BadInput{"k-DOP family beyond an int", [](json& d) { d["collision"] = {{"dop", 4294967324u}}; },
                 "collision.dop", "8, 28 or 80"},
        BadInput{"fractional k-DOP family", [](json& d) { d["collision"] = {{"dop", 28.5}}; }, "collision.dop",
                 "8, 28 or 80"},
        BadInput{"box grid above one", [](json& d) { d["collision"] = {{"box_resolution", 1.5}}; },
                 "collision.box_resolution", "between 0"},
        BadInput{"empty frame", [](json& d) { d["collision"] = {{"frame", 0}}; }, "collision.frame", "a frame must last"},
        BadInput{"conservative as a number", [](json& d) { d["collision"] = {{"conservative", 1}}; },
                 "collision.conservative", "expected"},
        BadInput{"negative clearance", [](json& d) { d["collision"] = {{"clearance", -0.001}}; }, "collision.clearance",
                 "the clearance must be a distance"},
        BadInput{"view with zero distance",
                 [](json& d) {
                   d["view"] = {{"target", {0, 0, 0}}, {"distance", 0}, {"yaw_degrees", 0}, {"pitch_degrees", 0}};
                 },
                 "view.distance", "must be positive"},
        BadInput{"view looking straight down",
                 [](json& d) {
                   d["view"] = {{"target", {0, 0, 0}}, {"distance", 1}, {"yaw_degrees", 0}, {"pitch_degrees", 90}};
                 },
                 "view.pitch_degrees", "between -90 and 90"},
        BadInput{"view without a target",
                 [](json& d) { d["view"] = {{"distance", 1}, {"yaw_degrees", 0}, {"pitch_degrees", 0}}; },
                 "view.target", "missing required field"},
        BadInput{"unknown interpolation",
                 [](json& d) { d["transitions"][0]["tracks"]["lid"]["interpolation"] = "linear"; },
                 "transitions[0].tracks.lid.interpolation", "unknown interpolation"}),
    [](const ::testing::TestParamInfo<BadInput>& param) {
      std::string name = param.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

TEST(SceneFile, MalformedJsonNamesLineAndColumn) {
  try {
    parse_scene("{\n  \"format\": \"reconfig-scene\",\n  \"version\": 1,,\n}", fs::current_path(), "bad.json");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "bad.json");
    EXPECT_NE(error.message().find("line 3"), std::string::npos) << error.what();
  }
}

TEST(SceneFile, NumberTooLargeForADoubleIsAnInputError) {
  std::string text = valid_scene().dump();
  text.replace(text.find("0.45"), 4, "0.3e827");
  try {
    parse_scene(text, fs::current_path(), "huge.json");
    FAIL() << "accepted a number beyond the range of a double";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "huge.json");
    EXPECT_NE(error.message().find("number overflow"), std::string::npos) << error.what();
  }
}

TEST(SceneFile, MissingFileSaysSo) {
  try {
    load_scene("/nonexistent/scene.json");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "/nonexistent/scene.json: file not found");
  }
}

TEST(SceneFile, NonManifoldMeshIsRejected) {
  const fs::path dir = testing::fresh_temp_dir();
  // Three triangles sharing one edge: a non-manifold "book".
  std::ofstream(dir / "book.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                     "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
  json document = valid_scene();
  document["parts"][1] = {{"name", "book"}, {"mesh", "book.obj"}};
  std::ofstream(dir / "scene.json") << document.dump();
  try {
    load_scene(dir / "scene.json");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "parts[1].mesh");
    EXPECT_NE(error.message().find("non-manifold"), std::string::npos) << error.what();
  }
}

/// Random mutations of a valid file: the loader either accepts it or throws InputError.
TEST(SceneFile, FuzzedFilesNeverCrash) {
  const std::string text = with_collision_settings(valid_scene()).dump(1);
  std::mt19937 random(7);
  int accepted = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string mutated = text;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = random() % mutated.size();
      switch (random() % 6) {
        case 0: mutated[at] = static_cast<char>(random() % 128); break;
        case 1: mutated.erase(at, 1 + random() % 8); break;
        case 2: mutated.insert(at, 1, "{}[],:\"0-.e"[random() % 11]); break;
        case 3: mutated.insert(at, 1 + random() % 100'000, "[{"[random() % 2]); break;  // deep nesting
        case 4: mutated.insert(random() % mutated.size(), mutated.substr(at, 1 + random() % 40)); break;  // repeats keys
        default: mutated = mutated.substr(0, at); break;
      }
      if (mutated.empty()) mutated.push_back('{');  // (`= "{"` gets a false -Wrestrict from GCC 12, bug 105329)
    }
    try {
      parse_scene(mutated, fs::current_path(), "fuzz.json");
      ++accepted;
    } catch (const InputError&) {
    }
  }
  std::printf("[ fuzz     ] 3000 mutated scenes, %d accepted\n", accepted);
  EXPECT_LT(accepted, 3000);
}

}  // namespace
}  // namespace reconfig::scene
