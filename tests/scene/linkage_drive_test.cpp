// Linkage-driven transitions: the "linkage" drive of the scene format, compiled into screw
// tracks (include/reconfig/scene/linkage_drive.h).

#include "reconfig/scene/linkage_drive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

#include "reconfig/common/input_error.h"
#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/linkage_motion.h"
#include "reconfig/linkage/symbolic_kinematics.h"
#include "reconfig/scene/edits.h"
#include "reconfig/scene/history.h"
#include "reconfig/scene/linkage_drive_edits.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/scene/validate_scene.h"
#include "support/test_data.h"

namespace reconfig::scene {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

fs::path linkages_dir() { return testing::source_dir() / "examples" / "linkages"; }
fs::path walker() { return testing::source_dir() / "examples" / "linkage-walker" / "scene.json"; }

json four_bar() { return json::parse(std::ifstream(linkages_dir() / "four_bar_crank_rocker.json")); }

/// A crank-rocker four-bar (inline) carrying three bars in three planes, turning 270° from 45°;
/// a ball that is not driven.
json driven_scene() {
  json document = json::parse(R"({
    "format": "reconfig-scene", "version": 1, "units": "m",
    "parts": [
      {"name": "crank", "box": {"size": [0.14, 0.04, 0.01]}},
      {"name": "coupler", "box": {"size": [0.36, 0.04, 0.01]}},
      {"name": "rocker", "box": {"size": [0.34, 0.04, 0.01]}},
      {"name": "ball", "sphere": {"radius": 0.05}}
    ],
    "states": [
      {"name": "start", "poses": {"ball": {"translation": [1, 0, 0]}}},
      {"name": "end", "poses": {"ball": {"translation": [1, 0, 0]}}}
    ],
    "transitions": [
      {"name": "turn", "from": "start", "to": "end",
       "linkage": {
         "plane": {"translation": [0, 0, 0.5], "rotation": [0.7071067811865476, 0.7071067811865476, 0, 0]},
         "scale": 0.1,
         "motor": {"from": 45, "to": 315},
         "tolerance": 0.0001,
         "attach": [
           {"part": "crank", "link": ["A", "B"], "offset": {"translation": [0.05, 0, 0.0]}},
           {"part": "coupler", "link": ["B", "C"], "offset": {"translation": [0.16, 0, 0.015]}},
           {"part": "rocker", "link": ["D", "C"], "offset": {"translation": [0.15, 0, 0.03], "rotation": [1, 0, 0, 0]}}
         ]}}
    ]})");
  document["transitions"][0]["linkage"]["inline"] = four_bar();
  return document;
}

Reconfigurable parse(const json& document, const fs::path& base = linkages_dir()) {
  return parse_scene(document.dump(), base, "test.json");
}

double part_radius(const Part& part) {
  return (part.mesh.V.rowwise() - part.center.transpose()).rowwise().norm().maxCoeff();
}

/// Largest distance, over `samples` + 1 evenly spaced times and over every vertex-ball point of
/// each driven part, between the compiled track (pose_at) and the exact linkage motion.
double measured_deviation(const Reconfigurable& scene, int transition, int samples) {
  std::vector<double> times;
  for (int s = 0; s <= samples; ++s) times.push_back(static_cast<double>(s) / samples);
  double worst = 0;
  for (const LinkageAttachment& a : scene.transitions[transition].linkage->attach) {
    const int part = scene.find_part(a.part);
    const Part& p = scene.parts[part];
    const std::vector<motion::Pose> truth = linkage_drive_poses(scene, transition, part, times);
    for (std::size_t k = 0; k < times.size(); ++k)
      worst = std::max(worst, linkage::placement_distance(scene.pose_at(transition, part, times[k]).to_isometry(p.center),
                                                          truth[k].to_isometry(p.center), p.center, part_radius(p)));
  }
  return worst;
}

TEST(LinkageDrive, CompilesIntoScrewTracksAndDefinesTheEndStates) {
  const Reconfigurable scene = parse(driven_scene());
  const Transition& turn = scene.transitions[0];
  ASSERT_TRUE(turn.linkage);
  EXPECT_FALSE(turn.linkage->file);
  for (const char* part : {"crank", "coupler", "rocker"}) {
    ASSERT_TRUE(turn.tracks.count(part)) << part;
    const auto* track = std::get_if<ScrewPosesTrack>(&turn.tracks.at(part));
    ASSERT_TRUE(track) << part;
    EXPECT_GT(track->poses.size(), 20u) << part;
    // The drive defined the state poses, at motor angles 45° and 315°.
    EXPECT_TRUE(poses_match(scene.states[0].pose_of(part), track->poses.front().pose));
    EXPECT_TRUE(poses_match(scene.states[1].pose_of(part), track->poses.back().pose));
  }
  EXPECT_FALSE(turn.tracks.count("ball"));
  EXPECT_LE(turn.linkage->compiled_deviation, 0.5e-4);
}

// Oracle: the pose of a driven part at time t equals what the symbolic kinematics gives at the
// motor angle 45° + 270° t, carried into 3D by the plane and the link frame.
TEST(LinkageDrive, PosesEqualTheSymbolicKinematicsAtTheMotorAngle) {
  const Reconfigurable scene = parse(driven_scene());
  const linkage::Linkage mechanism = linkage::parse_linkage(four_bar().dump());
  const linkage::SymbolicKinematics kinematics(mechanism, linkage::order_joints(mechanism));
  const int A = mechanism.find_joint("A"), B = mechanism.find_joint("B"), C = mechanism.find_joint("C"),
            D = mechanism.find_joint("D");
  // Plane (x, y) → world (0.1 x, 0, 0.1 y + 0.5); the normal +z of the plane → world −y.
  const auto world = [](const Eigen::Vector2d& x, double lift) { return Eigen::Vector3d(0.1 * x.x(), -lift, 0.1 * x.y() + 0.5); };
  const int crank = scene.find_part("crank"), coupler = scene.find_part("coupler"), rocker = scene.find_part("rocker");
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {  // compiled keys include the initial grid (every 10°)
    Eigen::Matrix2Xd X;
    ASSERT_TRUE(kinematics.solve((45 + 270 * t) * std::numbers::pi / 180, X));
    // A point of a part at rest coordinates p is at pose.apply(center, p); the box parts are
    // centered at their origin and the offsets shift them along the link's x axis.
    const auto at = [&](int part, const Eigen::Vector3d& rest) {
      return scene.pose_at(0, part, t).apply(scene.parts[part].center, rest);
    };
    const double lAB = 0.1 * (X.col(B) - X.col(A)).norm(), lBC = 0.1 * (X.col(C) - X.col(B)).norm(),
                 lDC = 0.1 * (X.col(C) - X.col(D)).norm();
    EXPECT_LT((at(crank, {-0.05, 0, 0}) - world(X.col(A), 0)).norm(), 1e-6) << t;
    EXPECT_LT((at(crank, {lAB - 0.05, 0, 0}) - world(X.col(B), 0)).norm(), 1e-6) << t;
    EXPECT_LT((at(coupler, {-0.16, 0, 0}) - world(X.col(B), 0.015)).norm(), 1e-6) << t;
    EXPECT_LT((at(coupler, {lBC - 0.16, 0, 0}) - world(X.col(C), 0.015)).norm(), 1e-6) << t;
    EXPECT_LT((at(rocker, {-0.15, 0, 0}) - world(X.col(D), 0.03)).norm(), 1e-6) << t;
    EXPECT_LT((at(rocker, {lDC - 0.15, 0, 0}) - world(X.col(C), 0.03)).norm(), 1e-6) << t;
  }
}

// The compiled tracks stay within the drive's tolerance of the exact motion, measured densely.
TEST(LinkageDrive, CompiledTracksStayWithinTheToleranceOfTheLinkage) {
  const Reconfigurable scene = parse(driven_scene());
  const double measured = measured_deviation(scene, 0, 20000);
  std::printf("four-bar drive (tolerance 1e-4 m): deviation measured at 20001 times %.3g m\n", measured);
  EXPECT_LE(measured, 1e-4);

  const Reconfigurable example = load_scene(walker());
  for (int tr = 0; tr < static_cast<int>(example.transitions.size()); ++tr) {
    const double walk = measured_deviation(example, tr, 20000);
    std::printf("linkage-walker \"%s\" (tolerance %g m): deviation measured at 20001 times %.3g m\n",
                example.transitions[tr].name.c_str(), example.transitions[tr].linkage->tolerance, walk);
    EXPECT_LE(walk, example.transitions[tr].linkage->tolerance);
  }
}

TEST(LinkageDrive, RoundTripIsLossless) {
  const Reconfigurable scene = parse(driven_scene());
  const std::string once = scene_to_json(scene, linkages_dir());
  const json saved = json::parse(once);
  // The drive is written, not the compiled keys.
  EXPECT_TRUE(saved["transitions"][0]["tracks"].empty());
  EXPECT_EQ(saved["transitions"][0]["linkage"]["inline"], four_bar());
  const Reconfigurable again = parse_scene(once, linkages_dir(), "again.json");
  EXPECT_EQ(scene_to_json(again, linkages_dir()), once);
  for (const char* part : {"crank", "coupler", "rocker"}) {
    const auto& a = std::get<ScrewPosesTrack>(scene.transitions[0].tracks.at(part)).poses;
    const auto& b = std::get<ScrewPosesTrack>(again.transitions[0].tracks.at(part)).poses;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].time, b[k].time);
      EXPECT_EQ(a[k].pose.translation, b[k].pose.translation);
      EXPECT_EQ(a[k].pose.rotation.coeffs(), b[k].pose.rotation.coeffs());
    }
  }
}

TEST(LinkageDrive, SavingElsewhereKeepsTheLinkageFileRelative) {
  Reconfigurable scene = load_scene(walker());
  const std::string original = scene_to_json(scene, walker().parent_path());
  const fs::path moved = testing::fresh_temp_dir() / "sub" / "walker.json";
  fs::create_directories(moved.parent_path());
  save_scene(scene, moved);
  const json saved = json::parse(std::ifstream(moved));
  const fs::path linkage_file = saved["transitions"][0]["linkage"]["file"].get<std::string>();
  EXPECT_TRUE(linkage_file.is_relative());
  EXPECT_TRUE(fs::equivalent(moved.parent_path() / linkage_file, linkages_dir() / "jansen.json"));
  const Reconfigurable again = load_scene(moved, {.allow_outside_paths = true});  // its meshes stayed behind
  EXPECT_EQ(scene_to_json(again, walker().parent_path()), original);
}

TEST(LinkageDrive, ExampleStatesAreDefinedByTheDrives) {
  const Reconfigurable scene = load_scene(walker());
  ASSERT_EQ(scene.transitions.size(), 2u);
  const int stacked = scene.find_state("stacked"), flat = scene.find_state("flat");
  ASSERT_GE(stacked, 0);
  ASSERT_GE(flat, 0);
  EXPECT_EQ(scene.states[stacked].poses.size(), 7u);  // every link; the frame stays at the identity
  EXPECT_EQ(scene.states[flat].poses.size(), 7u);
  // A full turn comes back: the last key equals the first.
  for (const auto& [part, track] : scene.transitions[0].tracks) {
    const auto& poses = std::get<ScrewPosesTrack>(track).poses;
    EXPECT_TRUE(poses_match(poses.front().pose, poses.back().pose, {1e-9, 1e-9})) << part;
  }
}

struct BadDrive {
  std::string what;
  std::function<void(json&)> mutate;
  std::string location;      ///< expected JSON path
  std::string message_part;  ///< expected substring of the message
};

class LinkageDriveErrors : public ::testing::TestWithParam<BadDrive> {};

TEST_P(LinkageDriveErrors, NameThePlace) {
  json document = driven_scene();
  GetParam().mutate(document);
  try {
    parse(document);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "test.json");
    EXPECT_EQ(error.location(), GetParam().location) << error.what();
    EXPECT_NE(error.message().find(GetParam().message_part), std::string::npos) << error.what();
  }
}

json& drive(json& d) { return d["transitions"][0]["linkage"]; }

/// The rocker variant of the four-bar: the motor turns D–C, which rocks between −141.4° and −101.4°.
json rocker() {
  json linkage = four_bar();
  linkage["motor"] = {{"center", "D"}, {"joint", "C"}};
  return linkage;
}

INSTANTIATE_TEST_SUITE_P(
    Scene, LinkageDriveErrors,
    ::testing::Values(
        BadDrive{"NoSource", [](json& d) { drive(d).erase("inline"); }, "transitions[0].linkage", "exactly one of"},
        BadDrive{"TwoSources", [](json& d) { drive(d)["file"] = "jansen.json"; }, "transitions[0].linkage",
                 "exactly one of"},
        BadDrive{"MissingFile",
                 [](json& d) {
                   drive(d).erase("inline");
                   drive(d)["file"] = "missing.json";
                 },
                 "transitions[0].linkage.file", "linkage file \"missing.json\" not found"},
        BadDrive{"BadLinkageFile",
                 [](json& d) {
                   drive(d).erase("inline");
                   drive(d)["file"] = "../linkage-walker/scene.json";  // a scene, not a linkage
                 },
                 "transitions[0].linkage.file", "../linkage-walker/scene.json: format: expected \"reconfig-linkage\""},
        BadDrive{"InlineNotAnObject", [](json& d) { drive(d)["inline"] = 3; }, "transitions[0].linkage.inline",
                 "expected a linkage object"},
        BadDrive{"InlineUnknownJoint", [](json& d) { drive(d)["inline"]["links"][1][1] = "Q"; },
                 "transitions[0].linkage.inline.links[1][1]", "unknown joint \"Q\""},
        BadDrive{"InlineUnderConstrained",
                 [](json& d) {
                   auto& links = drive(d)["inline"]["links"];
                   links = json::array({links[0], links[1]});  // no rocker: C and E float
                 },
                 "transitions[0].linkage.inline.joints[3]", "under-constrained"},
        BadDrive{"UnknownField", [](json& d) { drive(d)["speed"] = 2; }, "transitions[0].linkage.speed",
                 "unknown field"},
        BadDrive{"MissingMotor", [](json& d) { drive(d).erase("motor"); }, "transitions[0].linkage.motor",
                 "missing required field"},
        BadDrive{"MotorNotANumber", [](json& d) { drive(d)["motor"]["to"] = "360"; },
                 "transitions[0].linkage.motor.to", "expected a number"},
        BadDrive{"ZeroScale", [](json& d) { drive(d)["scale"] = 0; }, "transitions[0].linkage.scale",
                 "must be positive"},
        BadDrive{"NegativeTolerance", [](json& d) { drive(d)["tolerance"] = -1e-3; },
                 "transitions[0].linkage.tolerance", "must be positive"},
        BadDrive{"PlaneNotUnit", [](json& d) { drive(d)["plane"]["rotation"] = {1, 1, 0, 0}; },
                 "transitions[0].linkage.plane.rotation", "unit length"},
        BadDrive{"NoAttachments", [](json& d) { drive(d)["attach"] = json::array(); },
                 "transitions[0].linkage.attach", "at least one part"},
        BadDrive{"UnknownPart", [](json& d) { drive(d)["attach"][1]["part"] = "lid"; },
                 "transitions[0].linkage.attach[1].part", "unknown part \"lid\""},
        BadDrive{"AttachedTwice", [](json& d) { drive(d)["attach"][2]["part"] = "crank"; },
                 "transitions[0].linkage.attach[2].part", "attached twice"},
        BadDrive{"UnknownOriginJoint", [](json& d) { drive(d)["attach"][0]["link"][0] = "Z"; },
                 "transitions[0].linkage.attach[0].link[0]", "unknown joint \"Z\""},
        BadDrive{"UnknownTowardJoint", [](json& d) { drive(d)["attach"][0]["link"][1] = "Z"; },
                 "transitions[0].linkage.attach[0].link[1]", "unknown joint \"Z\""},
        BadDrive{"JointsOnNoCommonLink", [](json& d) { drive(d)["attach"][0]["link"] = {"A", "C"}; },
                 "transitions[0].linkage.attach[0].link", "not two joints of one link"},
        BadDrive{"LinkOfThreeJoints", [](json& d) { drive(d)["attach"][0]["link"] = {"B", "C", "E"}; },
                 "transitions[0].linkage.attach[0].link", "expected 2 elements"},
        BadDrive{"OffsetNotUnit", [](json& d) { drive(d)["attach"][0]["offset"]["rotation"] = {2, 0, 0, 0}; },
                 "transitions[0].linkage.attach[0].offset.rotation", "unit length"},
        BadDrive{"DrivenPartWithATrack",
                 [](json& d) {
                   d["transitions"][0]["tracks"]["coupler"] = json::parse(
                       R"({"interpolation": "screw", "poses": [{"time": 0, "translation": [0, 0, 0]}]})");
                 },
                 "transitions[0].tracks.coupler", "driven by the linkage"},
        BadDrive{"StatePoseDisagrees",
                 [](json& d) { d["states"][1]["poses"]["rocker"] = {{"translation", {0, 0, 0}}}; },
                 "states[1].poses.rocker", "does not match where the linkage of transition \"turn\" puts it"},
        BadDrive{"MotorLeavesTheRange",
                 [](json& d) {
                   drive(d)["inline"] = rocker();
                   drive(d)["motor"] = {{"from", -130}, {"to", -90}};
                 },
                 "transitions[0].linkage.motor", "cannot turn from -130.0° to -90.0°: the linkage rocks between"},
        BadDrive{"MotorTurnsTooFar", [](json& d) { drive(d)["motor"]["to"] = 1e300; },
                 "transitions[0].linkage.motor.to", "motor angles must lie within ±36000°"},
        BadDrive{"ToleranceTooSmall", [](json& d) { drive(d)["tolerance"] = 1e-15; },
                 "transitions[0].linkage.tolerance", "cannot be followed within 1e-15"},
        BadDrive{"PlaneTooFar", [](json& d) { drive(d)["plane"]["translation"] = {1e300, 0, 0}; },
                 "transitions[0].linkage.tolerance", "cannot be followed"},
        BadDrive{"UnknownState", [](json& d) { d["transitions"][0]["to"] = "nowhere"; }, "transitions[0].to",
                 "unknown state \"nowhere\""}),
    [](const ::testing::TestParamInfo<BadDrive>& param_info) { return param_info.param.what; });

TEST(LinkageDrive, ARockingLinkageMayTurnWithinItsRange) {
  json document = driven_scene();
  drive(document)["inline"] = rocker();
  drive(document)["motor"] = {{"from", 230}, {"to", 250}};  // −130° … −110°, one turn later
  drive(document)["attach"] = json::parse(R"([{"part": "rocker", "link": ["D", "C"]}])");
  const Reconfigurable scene = parse(document);
  EXPECT_LE(measured_deviation(scene, 0, 2000), 1e-4);
}

TEST(LinkageDrive, EditingADrivenPartsKeysIsRefused) {
  Reconfigurable scene = parse(driven_scene());
  const std::string before = scene_to_json(scene, linkages_dir());
  History history;
  EXPECT_THROW(history.execute(scene, insert_key("turn", "coupler", KeyKind::kTranslation, 0.123)), InputError);
  motion::Pose pose;
  pose.translation = {0.3, 0.2, 0.1};
  EXPECT_THROW(history.execute(scene, set_state_pose("end", "crank", pose)), InputError);
  EXPECT_EQ(scene_to_json(scene, linkages_dir()), before);
  // Editing a part the drive does not carry still works.
  pose.translation = {1, 0, 0.2};
  EXPECT_NO_THROW(history.execute(scene, set_state_pose("end", "ball", pose)));
  // validate_scene names the edited track.
  std::get<ScrewPosesTrack>(scene.transitions[0].tracks.at("rocker")).poses[3].time += 1e-6;
  try {
    validate_scene(scene);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "transitions[0].tracks.rocker");
  }
}

TEST(LinkageDrive, RecompilingAfterEditingTheDrive) {
  Reconfigurable scene = parse(driven_scene());
  LinkageDrive& drive = *scene.transitions[0].linkage;
  drive.to = 405;  // a whole turn
  drive.attach.pop_back();  // the rocker is no longer carried
  const std::string before = scene_to_json(scene, linkages_dir());
  const auto rocker_track = std::get<ScrewPosesTrack>(scene.transitions[0].tracks.at("rocker")).poses.size();
  try {  // the end state still holds the old poses
    compile_linkage_drive(scene, 0);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location(), "states[1].poses.crank") << error.what();
    EXPECT_NE(error.message().find("at motor angle 405°"), std::string::npos) << error.what();
  }
  // A failed compile changes nothing.
  EXPECT_EQ(scene_to_json(scene, linkages_dir()), before);
  EXPECT_EQ(std::get<ScrewPosesTrack>(scene.transitions[0].tracks.at("rocker")).poses.size(), rocker_track);
  compile_linkage_drive(scene, 0, DriveStatePoses::kOverwrite);
  EXPECT_FALSE(scene.transitions[0].tracks.count("rocker"));
  EXPECT_TRUE(poses_match(scene.states[0].pose_of("crank"), scene.states[1].pose_of("crank")));
  // The rocker's state poses differ (45° vs 315°) but it has no track now: the scene says so.
  EXPECT_THROW(validate_scene(scene), InputError);
  scene.states[1].poses["rocker"] = scene.states[0].poses["rocker"];
  EXPECT_NO_THROW(validate_scene(scene));
  EXPECT_LE(measured_deviation(scene, 0, 4000), 1e-4);
}

TEST(LinkageDrive, PosesOfAPartThatIsNotDrivenAreRefused) {
  const Reconfigurable scene = parse(driven_scene());
  EXPECT_THROW(linkage_drive_poses(scene, 0, scene.find_part("ball"), {0.5}), InputError);
}

}  // namespace
}  // namespace reconfig::scene

namespace reconfig::scene {
namespace {

TEST(LinkageDriveEdits, SetLinkageDriveIsUndoable) {
  Reconfigurable scene = parse(driven_scene());
  const std::string before = scene_to_json(scene, linkages_dir());
  LinkageDrive drive = *scene.transitions[0].linkage;
  drive.to = 225;
  drive.attach.pop_back();  // the rocker is no longer carried ...
  drive.attach.push_back({"ball", "D", "C", {}});  // ... and the ball rides on the rocker
  History history;
  // The rocker's state poses (45° and 315°) now differ while it has no track: refused as a whole.
  EXPECT_THROW(history.execute(scene, set_linkage_drive("turn", drive)), InputError);
  EXPECT_EQ(scene_to_json(scene, linkages_dir()), before);

  drive.attach.front().offset.translation.z() = 0.005;
  drive.attach.pop_back();
  drive.attach.push_back({"rocker", "D", "C", {}});
  const DirtySet dirty = history.execute(scene, set_linkage_drive("turn", drive));
  EXPECT_EQ(dirty.ranges.size(), 3u);  // crank, coupler, rocker over the whole transition
  const std::string after = scene_to_json(scene, linkages_dir());
  EXPECT_NE(after, before);
  EXPECT_EQ(json::parse(after)["transitions"][0]["linkage"]["motor"]["to"], 225.0);
  EXPECT_LE(measured_deviation(scene, 0, 2000), 1e-4);
  // The end state follows the drive.
  EXPECT_TRUE(poses_match(scene.states[1].pose_of("crank"),
                          std::get<ScrewPosesTrack>(scene.transitions[0].tracks.at("crank")).poses.back().pose));
  history.undo(scene);
  EXPECT_EQ(scene_to_json(scene, linkages_dir()), before);
  history.redo(scene);
  EXPECT_EQ(scene_to_json(scene, linkages_dir()), after);

  // Removing the drive keeps the motion as plain screw tracks.
  history.execute(scene, set_linkage_drive("turn", std::nullopt));
  EXPECT_FALSE(scene.transitions[0].linkage);
  const json saved = json::parse(scene_to_json(scene, linkages_dir()));
  EXPECT_EQ(saved["transitions"][0]["tracks"]["crank"]["interpolation"], "screw");
  EXPECT_NO_THROW(parse(saved));
  EXPECT_THROW(history.execute(scene, set_linkage_drive("nowhere", drive)), InputError);
}

}  // namespace
}  // namespace reconfig::scene

namespace reconfig::scene {
namespace {

/// Every leaf of `value` (objects and arrays walked), as JSON pointers.
void leaves(const json& value, const std::string& at, std::vector<std::string>& out) {
  if (value.is_object()) {
    for (const auto& item : value.items()) leaves(item.value(), at + "/" + item.key(), out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) leaves(value[i], at + "/" + std::to_string(i), out);
  }
  out.push_back(at);  // containers too: replacing a whole object is a mutation as well
}

// Fuzz: random replacements anywhere in a driven transition give an InputError or a valid
// scene — never another exception, a crash or a hang.
TEST(LinkageDriveFuzz, RandomMutationsAreInputErrors) {
  std::mt19937 rng(4);
  const json base = driven_scene();
  std::vector<std::string> paths;
  leaves(base["transitions"][0], "/transitions/0", paths);
  const std::vector<json> values = {nullptr, 0, -1, 1e300, -7.5, 720, "B", "", "Q", true,
                                    json::array(), json::array({1, 2}), json::array({"A", "A"}),
                                    json::array({0, 0, 0, 0}), json::object(), json::parse(R"({"from": 0})")};
  int loaded = 0;
  for (int trial = 0; trial < 400; ++trial) {
    json document = base;
    const int mutations = 1 + static_cast<int>(rng() % 3);
    for (int m = 0; m < mutations; ++m) {
      const json::json_pointer at(paths[rng() % paths.size()]);
      if (!document.contains(at)) continue;
      document[at] = values[rng() % values.size()];
    }
    try {
      parse(document);
      ++loaded;
    } catch (const InputError&) {
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what() << "\n" << document["transitions"][0].dump();
    }
  }
  EXPECT_GT(loaded, 0);  // some mutations are harmless (a motor angle, a tolerance, ...)
}

}  // namespace
}  // namespace reconfig::scene
