// Rotations in scene files as a person types them: an angle about an axis, or Euler angles in
// a stated order, besides unit quaternions; errors name the JSON path; saving writes
// quaternions (docs/file-formats.md).

#include <gtest/gtest.h>

#include <cctype>
#include <functional>
#include <nlohmann/json.hpp>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

/// A door that turns 90° about z, every rotation written as `rotation` (a quaternion for now).
json door_scene(const json& rotation) {
  json document = json::parse(R"({
    "format": "reconfig-scene", "version": 1,
    "parts": [{"name": "door", "box": {"size": [0.6, 0.02, 0.8]}}],
    "states": [{"name": "shut", "poses": {}}, {"name": "open", "poses": {"door": {}}}],
    "transitions": [{"name": "swing", "from": "shut", "to": "open",
      "tracks": {"door": {"rotation": [{"time": 0, "quaternion": [1, 0, 0, 0]}, {"time": 1}]}}}]})");
  document["states"][1]["poses"]["door"]["rotation"] = rotation;
  document["transitions"][0]["tracks"]["door"]["rotation"][1]["rotation"] = rotation;
  return document;
}

Reconfigurable parse(const json& document) { return parse_scene(document.dump(), fs::current_path(), "door.json"); }

const Eigen::Quaterniond kQuarterTurnAboutZ(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));

TEST(RotationForms, AxisAndDegrees) {
  const Reconfigurable scene = parse(door_scene({{"axis", {0, 0, 2}}, {"degrees", 90}}));  // any length of axis
  EXPECT_LT(scene.states[1].poses.at("door").rotation.angularDistance(kQuarterTurnAboutZ), 1e-15);
  EXPECT_LT(scene.pose_at(0, 0, 1.0).rotation.angularDistance(kQuarterTurnAboutZ), 1e-15);
  const Eigen::Quaterniond half(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()));
  EXPECT_LT(scene.pose_at(0, 0, 0.5).rotation.angularDistance(half), 1e-12);
}

TEST(RotationForms, EulerDegreesTurnAboutFixedAxesInTheStatedOrder) {
  // "xyz": first 90° about x, then 90° about the unmoved z (R = R_z R_y R_x).
  const Reconfigurable scene = parse(door_scene({{"euler_degrees", {90, 0, 90}}, {"order", "xyz"}}));
  const Eigen::Matrix3d R = scene.states[1].poses.at("door").rotation.toRotationMatrix();
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX())).toRotationMatrix();
  EXPECT_TRUE(R.isApprox(expected, 1e-14)) << R;
  // The order matters: "zyx" turns about z first.
  const Reconfigurable other = parse(door_scene({{"euler_degrees", {90, 0, 90}}, {"order", "zyx"}}));
  const Eigen::Matrix3d S = other.states[1].poses.at("door").rotation.toRotationMatrix();
  EXPECT_TRUE(S.isApprox((Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()) *
                          Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())).toRotationMatrix(), 1e-14));
  EXPECT_FALSE(S.isApprox(R, 1e-3));
  // Proper Euler angles (an axis again, not twice in a row): 90° about z, then about x, then z.
  EXPECT_NO_THROW(parse(door_scene({{"euler_degrees", {90, 0, 0}}, {"order", "zxz"}})));
}

TEST(RotationForms, SavedAsQuaternionsThatReadBackTheSame) {
  const Reconfigurable scene = parse(door_scene({{"axis", {0, 0, 1}}, {"degrees", 90}}));
  const json saved = json::parse(scene_to_json(scene, fs::current_path()));
  ASSERT_TRUE(saved["states"][1]["poses"]["door"]["rotation"].is_array());
  ASSERT_TRUE(saved["transitions"][0]["tracks"]["door"]["rotation"][1]["quaternion"].is_array());
  const Reconfigurable again = parse_scene(saved.dump(), fs::current_path(), "again.json");
  EXPECT_EQ(again.states[1].poses.at("door").rotation.coeffs(), scene.states[1].poses.at("door").rotation.coeffs());
  for (double t : {0.0, 0.3, 1.0})
    EXPECT_EQ(again.pose_at(0, 0, t).rotation.coeffs(), scene.pose_at(0, 0, t).rotation.coeffs()) << t;
}

TEST(RotationForms, ScrewPosesTakeThemToo) {
  json document = door_scene({1, 0, 0, 0});
  document["states"][1]["poses"]["door"]["rotation"] = {{"axis", {0, 0, 1}}, {"degrees", 90}};
  document["transitions"][0]["tracks"]["door"] = json::parse(R"({"interpolation": "screw", "poses": [
      {"time": 0}, {"time": 1, "rotation": {"euler_degrees": [0, 0, 90], "order": "xyz"}}]})");
  const Reconfigurable scene = parse(document);
  EXPECT_LT(scene.pose_at(0, 0, 1.0).rotation.angularDistance(kQuarterTurnAboutZ), 1e-12);
}

struct BadRotation {
  std::string what;
  json rotation;          ///< written as the open state's pose and as the last key
  std::string location;   ///< expected JSON path (in the state)
  std::string message_part;
};

void PrintTo(const BadRotation& bad, std::ostream* out) { *out << bad.what << ": " << bad.rotation.dump(); }

class RotationFormErrors : public ::testing::TestWithParam<BadRotation> {};

TEST_P(RotationFormErrors, NameThePlace) {
  try {
    parse(door_scene(GetParam().rotation));
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "states[1].poses.door.rotation" + GetParam().location) << error.what();
    EXPECT_NE(error.message().find(GetParam().message_part), std::string::npos) << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scene, RotationFormErrors,
    ::testing::Values(
        BadRotation{"zero axis", {{"axis", {0, 0, 0}}, {"degrees", 90}}, ".axis", "nonzero"},
        BadRotation{"axis of two numbers", {{"axis", {0, 1}}, {"degrees", 90}}, ".axis", "expected 3 elements"},
        BadRotation{"degrees missing", {{"axis", {0, 0, 1}}}, ".degrees", "missing required field"},
        BadRotation{"degrees as text", {{"axis", {0, 0, 1}}, {"degrees", "90"}}, ".degrees", "expected a number"},
        BadRotation{"radians", {{"axis", {0, 0, 1}}, {"radians", 1.5}}, ".radians", "unknown field"},
        BadRotation{"euler without order", {{"euler_degrees", {0, 0, 90}}}, ".order", "missing required field"},
        BadRotation{"euler order of two axes", {{"euler_degrees", {0, 0, 90}}, {"order", "xy"}}, ".order",
                    "three of x, y, z"},
        BadRotation{"euler axis twice in a row", {{"euler_degrees", {0, 0, 90}}, {"order", "xxz"}}, ".order",
                    "no axis twice"},
        BadRotation{"euler mixed with axis", {{"euler_degrees", {0, 0, 90}}, {"order", "xyz"}, {"axis", {0, 0, 1}}},
                    ".axis", "unknown field"},
        BadRotation{"a number", 90, "", "expected a quaternion [w, x, y, z], {\"axis\", \"degrees\"}"},
        BadRotation{"non-unit quaternion", {1, 1, 0, 0}, "", "unit length"}),
    [](const ::testing::TestParamInfo<BadRotation>& param) {
      std::string name = param.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

TEST(RotationForms, AKeyGivesExactlyOneOfQuaternionAndRotation) {
  json document = door_scene({{"axis", {0, 0, 1}}, {"degrees", 90}});
  document["transitions"][0]["tracks"]["door"]["rotation"][1]["quaternion"] = {1, 0, 0, 0};
  try {
    parse(document);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "transitions[0].tracks.door.rotation[1]") << error.what();
    EXPECT_NE(error.message().find("exactly one of \"quaternion\", \"rotation\""), std::string::npos) << error.what();
  }
}

TEST(RotationForms, AKeyThatDisagreesWithItsStateIsNamed) {
  json document = door_scene({{"axis", {0, 0, 1}}, {"degrees", 90}});
  document["transitions"][0]["tracks"]["door"]["rotation"][1]["rotation"]["degrees"] = 80;
  try {
    parse(document);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "transitions[0].tracks.door.rotation[1]") << error.what();
    EXPECT_NE(error.message().find("state \"open\""), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace reconfig::scene
