#include "reconfig/scene/linkage_drive.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <numbers>
#include <set>
#include <tuple>

#include "reconfig/common/input_error.h"
#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/linkage_motion.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::scene {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw InputError("", path, message); }

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

constexpr double kMaxMotorAngle = 36000;  // degrees: continuation through Newton blocks walks there

std::string full_vector(const Eigen::Vector3d& v) { return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z()); }
std::string full_quaternion(const Eigen::Quaterniond& q) {
  return fmt::format("[{}, {}, {}, {}]", q.w(), q.x(), q.y(), q.z());
}

/// Everything needed to evaluate a drive: the kinematics, the placement, the attached bodies.
struct PreparedDrive {
  std::unique_ptr<linkage::SymbolicKinematics> kinematics;
  linkage::PlanePlacement plane;
  std::vector<linkage::AttachedBody> bodies;
  std::vector<int> parts;  ///< scene part index per body
  double from = 0, to = 0;  ///< radians
};

double part_radius(const Part& part) {
  if (part.mesh.V.rows() == 0) return 0.0;
  return (part.mesh.V.rowwise() - part.center.transpose()).rowwise().norm().maxCoeff();
}

/// Checks the drive of transition `index` against the scene and builds its kinematics.
PreparedDrive prepare(const Reconfigurable& scene, int index) {
  const Transition& transition = scene.transitions.at(index);
  const LinkageDrive& drive = *transition.linkage;
  const std::string path = fmt::format("transitions[{}].linkage", index);
  const linkage::Linkage& mechanism = drive.linkage;

  if (!(std::isfinite(drive.scale) && drive.scale > 0))
    fail(path + ".scale", fmt::format("scale must be a positive number, found {}", drive.scale));
  if (!(std::isfinite(drive.tolerance) && drive.tolerance > 0))
    fail(path + ".tolerance", fmt::format("tolerance must be a positive number, found {}", drive.tolerance));
  for (const auto& [angle, field] : {std::pair{drive.from, ".motor.from"}, std::pair{drive.to, ".motor.to"}})
    if (!(std::abs(angle) <= kMaxMotorAngle))
      fail(path + field, fmt::format("motor angles must lie within ±{}° (100 turns), found {}", kMaxMotorAngle, angle));
  if (!drive.plane.translation.allFinite()) fail(path + ".plane.translation", "coordinates must be finite numbers");
  if (!drive.plane.rotation.coeffs().allFinite() || std::abs(drive.plane.rotation.norm() - 1.0) > 1e-3)
    fail(path + ".plane.rotation", "quaternion must have unit length");
  if (drive.attach.empty()) fail(path + ".attach", "attach at least one part to a link");

  PreparedDrive prepared;
  const std::string source = path + (drive.file ? ".file" : ".inline");
  try {
    prepared.kinematics = std::make_unique<linkage::SymbolicKinematics>(mechanism, linkage::order_joints(mechanism));
  } catch (const InputError& error) {
    if (drive.file) fail(source, error.in_file(drive.file->filename().string()).what());
    fail(error.location().empty() ? source : source + "." + error.location(), error.message());
  }
  prepared.plane.pose = drive.plane.to_isometry(Eigen::Vector3d::Zero());
  prepared.plane.scale = drive.scale;
  prepared.from = radians(drive.from);
  prepared.to = radians(drive.to);

  std::set<std::string> attached;
  for (std::size_t k = 0; k < drive.attach.size(); ++k) {
    const LinkageAttachment& a = drive.attach[k];
    const std::string at = fmt::format("{}.attach[{}]", path, k);
    const int part = scene.find_part(a.part);
    if (part < 0) fail(at + ".part", fmt::format("unknown part \"{}\"", a.part));
    if (!attached.insert(a.part).second)
      fail(at + ".part", fmt::format("part \"{}\" is attached twice (a part moves with one link)", a.part));
    const int origin = mechanism.find_joint(a.origin), toward = mechanism.find_joint(a.toward);
    if (origin < 0) fail(at + ".link[0]", fmt::format("unknown joint \"{}\"", a.origin));
    if (toward < 0) fail(at + ".link[1]", fmt::format("unknown joint \"{}\"", a.toward));
    if (!linkage::share_a_link(mechanism, origin, toward))
      fail(at + ".link", fmt::format("joints \"{}\" and \"{}\" are not two joints of one link", a.origin, a.toward));
    if (!a.offset.translation.allFinite()) fail(at + ".offset.translation", "coordinates must be finite numbers");
    if (!a.offset.rotation.coeffs().allFinite() || std::abs(a.offset.rotation.norm() - 1.0) > 1e-3)
      fail(at + ".offset.rotation", "quaternion must have unit length");
    linkage::AttachedBody body;
    body.attachment = {origin, toward, a.offset.to_isometry(Eigen::Vector3d::Zero())};
    body.center = scene.parts[part].center;
    body.radius = part_radius(scene.parts[part]);
    prepared.bodies.push_back(body);
    prepared.parts.push_back(part);
  }
  return prepared;
}

}  // namespace

bool LinkageDrive::drives(const std::string& part) const {
  return std::any_of(attach.begin(), attach.end(), [&](const LinkageAttachment& a) { return a.part == part; });
}

void compile_linkage_drive(Reconfigurable& scene, int index, DriveStatePoses state_poses) {
  Transition& transition = scene.transitions.at(index);
  const std::string path = fmt::format("transitions[{}]", index);
  if (!transition.linkage) fail(path, fmt::format("transition \"{}\" has no linkage drive", transition.name));
  LinkageDrive& drive = *transition.linkage;
  const int from_state = scene.find_state(transition.from), to_state = scene.find_state(transition.to);
  if (from_state < 0) fail(path + ".from", fmt::format("unknown state \"{}\"", transition.from));
  if (to_state < 0) fail(path + ".to", fmt::format("unknown state \"{}\"", transition.to));

  const PreparedDrive prepared = prepare(scene, index);
  // A driven part's track must be the one compiled from the drive before (or none).
  for (const LinkageAttachment& a : drive.attach) {
    const auto track = transition.tracks.find(a.part);
    if (track == transition.tracks.end()) continue;
    const auto compiled = drive.compiled.find(a.part);
    const auto* screw = std::get_if<ScrewPosesTrack>(&track->second);
    if (compiled == drive.compiled.end() || !screw || *screw != compiled->second)
      fail(fmt::format("{}.tracks.{}", path, a.part),
           fmt::format("part \"{}\" is driven by the linkage of this transition: remove its track", a.part));
  }

  const std::string motor = path + ".linkage.motor";
  const linkage::MotionRange range = linkage::motion_range(*prepared.kinematics);
  if (const std::string error = linkage::motor_interval_error(range, prepared.from, prepared.to); !error.empty())
    fail(motor, error);
  prepared.kinematics->reset_continuation();
  const linkage::LinkageMotion motion(*prepared.kinematics, prepared.plane, prepared.from, prepared.to);
  linkage::CompileMotionRequest request;
  request.bodies = prepared.bodies;
  request.tolerance = drive.tolerance;
  linkage::CompiledMotion compiled;
  try {
    compiled = linkage::compile_motion(motion, request);
  } catch (const InputError& error) {
    fail(error.location().empty() ? path + ".linkage" : path + ".linkage." + error.location(), error.message());
  }

  // The end states: the drive defines the poses of the parts it carries. Checked before
  // anything changes, so a failed compile leaves the scene as it was.
  std::vector<std::tuple<int, std::string, motion::Pose>> state_updates;
  for (const auto& [state, at_end, angle] :
       {std::tuple{from_state, false, drive.from}, std::tuple{to_state, true, drive.to}}) {
    const State& s = scene.states[state];
    for (std::size_t b = 0; b < prepared.parts.size(); ++b) {
      const std::string& name = scene.parts[prepared.parts[b]].name;
      const motion::Pose pose = at_end ? compiled.keys[b].back().pose : compiled.keys[b].front().pose;
      const auto listed = s.poses.find(name);
      const bool filled_here = std::any_of(state_updates.begin(), state_updates.end(), [&](const auto& update) {
        return std::get<0>(update) == state && std::get<1>(update) == name;
      });
      const motion::Pose* current = listed != s.poses.end() ? &listed->second : nullptr;
      for (const auto& update : state_updates)
        if (std::get<0>(update) == state && std::get<1>(update) == name) current = &std::get<2>(update);
      if (!current || (state_poses == DriveStatePoses::kOverwrite && !filled_here)) {
        state_updates.emplace_back(state, name, pose);
      } else if (!poses_match(*current, pose)) {
        fail(fmt::format("states[{}].poses.{}", state, name),
             fmt::format("the pose of part \"{}\" in state \"{}\" does not match where the linkage of transition "
                         "\"{}\" puts it at motor angle {}° (translation {}, rotation {}): remove the pose to let "
                         "the drive define it",
                         name, s.name, transition.name, angle, full_vector(pose.translation),
                         full_quaternion(pose.rotation)));
      }
    }
  }

  // Parts that the drive no longer carries lose the tracks it compiled for them.
  for (const auto& [part, track] : drive.compiled) {
    if (drive.drives(part)) continue;
    const auto it = transition.tracks.find(part);
    if (it != transition.tracks.end())
      if (const auto* screw = std::get_if<ScrewPosesTrack>(&it->second); screw && *screw == track)
        transition.tracks.erase(it);
  }
  drive.compiled.clear();
  drive.compiled_deviation = compiled.deviation;
  for (std::size_t b = 0; b < prepared.parts.size(); ++b) {
    const std::string& name = scene.parts[prepared.parts[b]].name;
    ScrewPosesTrack track{std::move(compiled.keys[b])};
    transition.tracks[name] = track;
    drive.compiled.emplace(name, std::move(track));
  }
  for (auto& [state, name, pose] : state_updates) scene.states[state].poses[name] = pose;
}

void compile_linkage_drives(Reconfigurable& scene, DriveStatePoses state_poses) {
  for (int i = 0; i < static_cast<int>(scene.transitions.size()); ++i)
    if (scene.transitions[i].linkage) compile_linkage_drive(scene, i, state_poses);
}

std::vector<motion::Pose> linkage_drive_poses(const Reconfigurable& scene, int transition, int part,
                                              const std::vector<double>& times) {
  const Transition& tr = scene.transitions.at(transition);
  const std::string& name = scene.parts.at(part).name;
  if (!tr.linkage || !tr.linkage->drives(name))
    throw InputError("", fmt::format("transitions[{}]", transition),
                     fmt::format("part \"{}\" is not driven by a linkage in transition \"{}\"", name, tr.name));
  const PreparedDrive prepared = prepare(scene, transition);
  const auto at = std::find(prepared.parts.begin(), prepared.parts.end(), part);
  const linkage::AttachedBody body = prepared.bodies[static_cast<std::size_t>(at - prepared.parts.begin())];
  const linkage::LinkageMotion motion(*prepared.kinematics, prepared.plane, prepared.from, prepared.to);
  std::vector<motion::Pose> poses;
  poses.reserve(times.size());
  for (double t : times) {
    try {
      poses.push_back(motion::Pose::from_isometry(motion.maps_at(t, {body}).front(), body.center));
    } catch (const InputError& error) {
      const std::string drive_path = fmt::format("transitions[{}].linkage", transition);
      fail(error.location().empty() ? drive_path : drive_path + "." + error.location(), error.message());
    }
  }
  return poses;
}

std::string edited_driven_part(const Transition& transition) {
  if (!transition.linkage) return "";
  for (const LinkageAttachment& a : transition.linkage->attach) {
    const auto track = transition.tracks.find(a.part);
    const auto compiled = transition.linkage->compiled.find(a.part);
    if (track == transition.tracks.end() || compiled == transition.linkage->compiled.end()) return a.part;
    const auto* screw = std::get_if<ScrewPosesTrack>(&track->second);
    if (!screw || *screw != compiled->second) return a.part;
  }
  return "";
}

}  // namespace reconfig::scene
