#include "reconfig/scene/scene_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "reconfig/common/input_error.h"
#include "reconfig/common/inside_folder.h"
#include "reconfig/common/read_input_file.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/scene/linkage_drive.h"
#include "common/detail/strict_json.h"
#include "reconfig/scene/validate_scene.h"
#include "scene/detail/json_cursor.h"
#include "scene/detail/rotation_json.h"
#include "scene/detail/translation_ease.h"

namespace reconfig::scene {
namespace fs = std::filesystem;
using detail::JsonCursor;
using detail::read_rotation;
using nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "reconfig-scene";
constexpr int kVersion = 1;

motion::Pose read_pose(const JsonCursor& c) {
  c.expect_object({"translation", "rotation"});
  motion::Pose pose;
  if (c.has("translation")) pose.translation = c["translation"].as_vector3();
  if (c.has("rotation")) pose.rotation = read_rotation(c["rotation"]);
  return pose;
}

/// Loads each distinct mesh file once, even when several parts share it.
class MeshCache {
 public:
  explicit MeshCache(const SceneLoadOptions& options) : options_{options.allow_outside_paths} {}

  const geometry::Mesh& get(const fs::path& path, const JsonCursor& where) {
    auto it = meshes_.find(path);
    if (it != meshes_.end()) return it->second;
    try {
      return meshes_.emplace(path, geometry::load_mesh(path, options_)).first->second;
    } catch (const InputError& error) {
      where.fail(error.what());
    }
  }

 private:
  geometry::MeshLoadOptions options_;
  std::map<fs::path, geometry::Mesh> meshes_;
};

/// The file a path written at `c` names, relative to `base_dir`, which it must not leave
/// unless `options` allow it.
fs::path referenced_file(const JsonCursor& c, const fs::path& base_dir, const SceneLoadOptions& options) {
  const std::string written = c.as_string();
  if (!options.allow_outside_paths) {
    try {
      if (const std::string problem = outside_folder_problem(base_dir, written); !problem.empty()) c.fail(problem);
    } catch (const InputError& error) {
      if (!error.location().empty()) throw;
      c.fail(error.message());
    }
  }
  return (base_dir / written).lexically_normal();
}

Part read_part(const JsonCursor& c, const fs::path& base_dir, const SceneLoadOptions& options, MeshCache& meshes) {
  c.expect_object({"name", "mesh", "box", "cylinder", "sphere", "color", "center"});
  Part part;
  part.name = c["name"].as_name();
  int sources = 0;
  for (const char* key : {"mesh", "box", "cylinder", "sphere"}) sources += c.has(key) ? 1 : 0;
  if (sources != 1) c.fail("a part needs exactly one of \"mesh\", \"box\", \"cylinder\", \"sphere\"");
  if (c.has("mesh")) {
    const JsonCursor mesh = c["mesh"];
    const fs::path path = referenced_file(mesh, base_dir, options);
    part.source = MeshFile{path};
    part.mesh = meshes.get(path, mesh);
    geometry::MeshCheckOptions quick;
    quick.check_self_intersections = false;
    const geometry::MeshReport report = geometry::check_mesh(part.mesh, quick);
    if (!report.is_manifold() || report.non_finite_vertices.any() || report.out_of_range_faces.any())
      mesh.fail("unusable mesh: " + report.summary());
  } else {
    if (c.has("box")) {
      const JsonCursor box = c["box"];
      box.expect_object({"size"});
      const JsonCursor sizes = box["size"];
      sizes.expect_array(3);
      const Eigen::Vector3d size(sizes[0].as_length(), sizes[1].as_length(), sizes[2].as_length());
      part.source = BoxPrimitive{size};
    } else if (c.has("cylinder")) {
      const JsonCursor cylinder = c["cylinder"];
      cylinder.expect_object({"radius", "height"});
      part.source = CylinderPrimitive{cylinder["radius"].as_length(), cylinder["height"].as_length()};
    } else {
      const JsonCursor sphere = c["sphere"];
      sphere.expect_object({"radius"});
      part.source = SpherePrimitive{sphere["radius"].as_length()};
    }
    part.mesh = Part::primitive_mesh(part.source);
  }
  if (c.has("color")) {
    const Eigen::Vector3d color = c["color"].as_vector3();
    if ((color.array() < 0).any() || (color.array() > 1).any()) c["color"].fail("color components must lie in [0, 1]");
    part.color = color;
  }
  part.center = c.has("center") ? c["center"].as_vector3() : part_center(part.mesh);
  return part;
}

State read_state(const JsonCursor& c) {
  c.expect_object({"name", "poses"});
  State state;
  state.name = c["name"].as_name();
  if (c.has("poses")) {
    const JsonCursor poses = c["poses"];
    if (!poses.value().is_object()) poses.fail("expected an object mapping part names to poses");
    for (const auto& item : poses.value().items()) state.poses.emplace(item.key(), read_pose(poses[item.key()]));
  }
  return state;
}

detail::WrittenTranslationKey read_translation_key(const JsonCursor& c) {
  c.expect_object({"time", "point", "in", "out"});
  detail::WrittenTranslationKey key;
  key.time = c["time"].as_number();
  key.point = c["point"].as_vector3();
  if (c.has("in")) key.in = c["in"].as_vector3();
  if (c.has("out")) key.out = c["out"].as_vector3();
  return key;
}

/// `quaternion` as ever, or `rotation` in any form `read_rotation` accepts.
motion::RotationKey read_rotation_key(const JsonCursor& c) {
  c.expect_object({"time", "quaternion", "rotation"});
  if (c.has("quaternion") == c.has("rotation")) c.fail("a rotation key needs exactly one of \"quaternion\", \"rotation\"");
  const double time = c["time"].as_number();
  return {time, c.has("quaternion") ? c["quaternion"].as_unit_quaternion() : read_rotation(c["rotation"])};
}

Track read_track(const JsonCursor& c) {
  const std::string interpolation = c.has("interpolation") ? c["interpolation"].as_string() : "bezier";
  if (interpolation == "screw") {
    c.expect_object({"interpolation", "poses"});
    ScrewPosesTrack track;
    const JsonCursor poses = c["poses"];
    const std::size_t n = poses.expect_array();
    if (n == 0) poses.fail("a screw track needs at least one key pose");
    for (std::size_t i = 0; i < n; ++i) {
      const JsonCursor key = poses[i];
      key.expect_object({"time", "translation", "rotation"});
      motion::Pose pose;
      if (key.has("translation")) pose.translation = key["translation"].as_vector3();
      if (key.has("rotation")) pose.rotation = read_rotation(key["rotation"]);
      track.poses.push_back({key["time"].as_number(), pose});
    }
    return track;
  }
  if (interpolation != "bezier")
    c["interpolation"].fail(fmt::format("unknown interpolation \"{}\" (expected \"bezier\" or \"screw\")", interpolation));
  c.expect_object({"interpolation", "ease", "translation", "rotation"});
  KeyframedTrack track;
  const detail::Ease ease = c.has("ease") ? detail::read_ease(c["ease"]) : detail::Ease::smooth;
  if (c.has("translation")) {
    const JsonCursor keys = c["translation"];
    const std::size_t n = keys.expect_array();
    if (n == 0) keys.fail("give at least one key, or leave the list out");
    std::vector<detail::WrittenTranslationKey> written;
    for (std::size_t i = 0; i < n; ++i) written.push_back(read_translation_key(keys[i]));
    track.translation = detail::ease_translation_keys(written, ease);
  }
  if (c.has("rotation")) {
    const JsonCursor keys = c["rotation"];
    const std::size_t n = keys.expect_array();
    if (n == 0) keys.fail("give at least one key, or leave the list out");
    for (std::size_t i = 0; i < n; ++i) track.rotation.push_back(read_rotation_key(keys[i]));
  }
  return track;
}

/// A pose written as a plain rigid map `q = R p + x` (the drive's plane and offsets).
motion::Pose read_placement(const JsonCursor& c) { return read_pose(c); }

linkage::Linkage read_drive_linkage(const JsonCursor& c, const fs::path& base_dir, LinkageDrive& drive) {
  if (c.has("file") == c.has("inline")) c.fail("a linkage drive needs exactly one of \"file\", \"inline\"");
  if (c.has("file")) {
    const JsonCursor file = c["file"];
    const std::string relative = file.as_string();
    // A linkage file may lie anywhere (examples share theirs from a sibling folder): its content
    // becomes joint positions, never mesh data a design could export.
    const fs::path path = (base_dir / relative).lexically_normal();
    drive.file = path;
    std::error_code unresolved;  // a symbolic link loop: read_linkage says so
    if (!fs::exists(path, unresolved) && !unresolved) file.fail(fmt::format("linkage file \"{}\" not found", relative));
    try {
      return linkage::read_linkage(path);
    } catch (const InputError& error) {
      file.fail(error.in_file(relative).what());
    }
  }
  const JsonCursor inline_linkage = c["inline"];
  if (!inline_linkage.value().is_object()) inline_linkage.fail("expected a linkage object (\"reconfig-linkage\")");
  try {
    linkage::Linkage result = linkage::parse_linkage(inline_linkage.value().dump());
    linkage::check_linkage(result);
    return result;
  } catch (const InputError& error) {
    throw InputError("", error.location().empty() ? inline_linkage.path() : inline_linkage.path() + "." + error.location(),
                     error.message());
  }
}

LinkageDrive read_drive(const JsonCursor& c, const fs::path& base_dir) {
  c.expect_object({"file", "inline", "plane", "scale", "motor", "tolerance", "attach"});
  LinkageDrive drive;
  drive.linkage = read_drive_linkage(c, base_dir, drive);
  if (c.has("plane")) drive.plane = read_placement(c["plane"]);
  if (c.has("scale")) drive.scale = c["scale"].as_positive();
  const JsonCursor motor = c["motor"];
  motor.expect_object({"from", "to"});
  drive.from = motor["from"].as_number();
  drive.to = motor["to"].as_number();
  if (c.has("tolerance")) drive.tolerance = c["tolerance"].as_positive();
  const JsonCursor attach = c["attach"];
  const std::size_t n = attach.expect_array();
  if (n == 0) attach.fail("attach at least one part to a link");
  for (std::size_t k = 0; k < n; ++k) {
    const JsonCursor a = attach[k];
    a.expect_object({"part", "link", "offset"});
    LinkageAttachment attachment;
    attachment.part = a["part"].as_name();
    const JsonCursor link = a["link"];
    link.expect_array(2);
    attachment.origin = link[0].as_name();
    attachment.toward = link[1].as_name();
    if (a.has("offset")) attachment.offset = read_placement(a["offset"]);
    drive.attach.push_back(std::move(attachment));
  }
  return drive;
}

Transition read_transition(const JsonCursor& c, const fs::path& base_dir) {
  c.expect_object({"name", "from", "to", "bidirectional", "tracks", "linkage"});
  Transition transition;
  transition.name = c["name"].as_name();
  transition.from = c["from"].as_name();
  transition.to = c["to"].as_name();
  if (c.has("bidirectional")) transition.bidirectional = c["bidirectional"].as_bool();
  if (c.has("tracks")) {
    const JsonCursor tracks = c["tracks"];
    if (!tracks.value().is_object()) tracks.fail("expected an object mapping part names to tracks");
    for (const auto& item : tracks.value().items())
      transition.tracks.emplace(item.key(), read_track(tracks[item.key()]));
  }
  if (c.has("linkage")) transition.linkage = read_drive(c["linkage"], base_dir);
  return transition;
}

CollisionSettings read_collision_settings(const JsonCursor& c) {
  c.expect_object(
      {"tolerance", "dop", "box_resolution", "frame", "conservative", "contact", "touching_collides", "clearance"});
  CollisionSettings settings;
  if (c.has("tolerance")) settings.tolerance = c["tolerance"].as_number();
  if (c.has("dop")) {
    const nlohmann::json& dop = c["dop"].value();  // compared as a number, so 2^32 + 28 is no 28
    const auto listed = [&](int halfspaces) { return dop == halfspaces; };
    if (!dop.is_number_integer() || std::none_of(kDopHalfspaces.begin(), kDopHalfspaces.end(), listed))
      c["dop"].fail("expected " + dop_halfspace_choices());
    settings.dop = dop.get<int>();
  }
  if (c.has("box_resolution")) settings.box_resolution = c["box_resolution"].as_number();
  if (c.has("frame")) settings.frame = c["frame"].as_number();
  if (c.has("conservative")) settings.conservative = c["conservative"].as_bool();
  if (c.has("contact")) settings.contact = c["contact"].as_number();
  if (c.has("touching_collides")) settings.touching_collides = c["touching_collides"].as_bool();
  if (c.has("clearance")) settings.clearance = c["clearance"].as_number();
  // Each setting on its own, so that the error names the one at fault.
  const auto check = [&](const char* key, auto CollisionSettings::*setting) {
    CollisionSettings only;
    only.*setting = settings.*setting;
    if (const std::string problem = only.problem(); !problem.empty()) c[key].fail(problem);
  };
  check("tolerance", &CollisionSettings::tolerance);  // (the family was checked as it was read)
  check("box_resolution", &CollisionSettings::box_resolution);
  check("frame", &CollisionSettings::frame);
  check("contact", &CollisionSettings::contact);
  check("clearance", &CollisionSettings::clearance);
  return settings;
}

SavedView read_view(const JsonCursor& c) {
  c.expect_object({"target", "distance", "yaw_degrees", "pitch_degrees"});
  SavedView view;
  view.target = c["target"].as_vector3();
  view.distance = c["distance"].as_positive();
  view.yaw_degrees = c["yaw_degrees"].as_number();
  view.pitch_degrees = c["pitch_degrees"].as_number();
  if (!(std::abs(view.pitch_degrees) < 90)) c["pitch_degrees"].fail("must be strictly between -90 and 90");
  return view;
}

Reconfigurable read_scene(const JsonCursor& root, const fs::path& base_dir, const SceneLoadOptions& options) {
  root.expect_object({"format", "version", "units", "ground", "parts", "states", "transitions", "collision", "view"});
  if (root["format"].as_string() != kFormat)
    root["format"].fail(fmt::format("expected \"{}\"", kFormat));
  const JsonCursor version = root["version"];
  if (!version.value().is_number_integer() || version.value() != kVersion)  // as a number: 2^32 + 1 is no 1
    version.fail(fmt::format("unsupported version: {} (this build reads version {})",
                             reconfig::detail::describe_json(version.value()), kVersion));
  Reconfigurable scene;
  if (root.has("units")) scene.units = root["units"].as_name();
  if (root.has("ground")) scene.ground = root["ground"].as_bool();
  MeshCache meshes(options);
  const JsonCursor parts = root["parts"];
  for (std::size_t i = 0, n = parts.expect_array(); i < n; ++i)
    scene.parts.push_back(read_part(parts[i], base_dir, options, meshes));
  const JsonCursor states = root["states"];
  for (std::size_t i = 0, n = states.expect_array(); i < n; ++i) scene.states.push_back(read_state(states[i]));
  if (root.has("transitions")) {
    const JsonCursor transitions = root["transitions"];
    for (std::size_t i = 0, n = transitions.expect_array(); i < n; ++i)
      scene.transitions.push_back(read_transition(transitions[i], base_dir));
  }
  if (root.has("collision")) scene.collision = read_collision_settings(root["collision"]);
  if (root.has("view")) scene.view = read_view(root["view"]);
  compile_linkage_drives(scene);
  validate_scene(scene);
  return scene;
}

ordered_json collision_settings_json(const CollisionSettings& settings) {
  ordered_json j = ordered_json::object();
  if (settings.tolerance) j["tolerance"] = *settings.tolerance;
  if (settings.dop) j["dop"] = *settings.dop;
  if (settings.box_resolution) j["box_resolution"] = *settings.box_resolution;
  if (settings.frame) j["frame"] = *settings.frame;
  if (settings.conservative) j["conservative"] = *settings.conservative;
  if (settings.contact) j["contact"] = *settings.contact;
  if (settings.touching_collides) j["touching_collides"] = *settings.touching_collides;
  if (settings.clearance) j["clearance"] = *settings.clearance;
  return j;
}

ordered_json vector_json(const Eigen::Vector3d& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }
ordered_json quaternion_json(const Eigen::Quaterniond& q) { return ordered_json::array({q.w(), q.x(), q.y(), q.z()}); }

ordered_json pose_json(const motion::Pose& pose) {
  return {{"translation", vector_json(pose.translation)}, {"rotation", quaternion_json(pose.rotation)}};
}

ordered_json part_json(const Part& part, const fs::path& base_dir) {
  ordered_json j;
  j["name"] = part.name;
  if (const auto* file = std::get_if<MeshFile>(&part.source)) {
    j["mesh"] = file->path.lexically_proximate(base_dir).generic_string();
  } else if (const auto* box = std::get_if<BoxPrimitive>(&part.source)) {
    j["box"] = {{"size", vector_json(box->size)}};
  } else if (const auto* cylinder = std::get_if<CylinderPrimitive>(&part.source)) {
    j["cylinder"] = {{"radius", cylinder->radius}, {"height", cylinder->height}};
  } else if (const auto* sphere = std::get_if<SpherePrimitive>(&part.source)) {
    j["sphere"] = {{"radius", sphere->radius}};
  } else {
    throw InputError("", "part " + part.name, "edited geometry must be written to a file before saving (use save_scene)");
  }
  if (part.color) j["color"] = vector_json(*part.color);
  if (part.center != part_center(part.mesh)) j["center"] = vector_json(part.center);
  return j;
}

ordered_json track_json(const Track& track) {
  ordered_json j;
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track)) {
    j["interpolation"] = "screw";
    ordered_json poses = ordered_json::array();
    for (const motion::ScrewKey& key : screw->poses) {
      ordered_json p = {{"time", key.time}};
      p.update(pose_json(key.pose));
      poses.push_back(p);
    }
    j["poses"] = poses;
    return j;
  }
  const auto& keyed = std::get<KeyframedTrack>(track);
  if (!keyed.translation.empty()) {
    ordered_json keys = ordered_json::array();
    for (const motion::TranslationKey& key : keyed.translation)
      keys.push_back({{"time", key.time}, {"point", vector_json(key.point)}, {"in", vector_json(key.in)},
                      {"out", vector_json(key.out)}});
    j["translation"] = keys;
  }
  if (!keyed.rotation.empty()) {
    ordered_json keys = ordered_json::array();
    for (const motion::RotationKey& key : keyed.rotation)
      keys.push_back({{"time", key.time}, {"quaternion", quaternion_json(key.rotation)}});
    j["rotation"] = keys;
  }
  return j;
}

ordered_json drive_json(const LinkageDrive& drive, const fs::path& base_dir) {
  ordered_json j;
  if (drive.file)
    j["file"] = drive.file->lexically_proximate(base_dir).generic_string();
  else
    j["inline"] = ordered_json::parse(linkage::linkage_to_json(drive.linkage));
  j["plane"] = pose_json(drive.plane);
  j["scale"] = drive.scale;
  j["motor"] = {{"from", drive.from}, {"to", drive.to}};
  j["tolerance"] = drive.tolerance;
  ordered_json attach = ordered_json::array();
  for (const LinkageAttachment& a : drive.attach)
    attach.push_back({{"part", a.part}, {"link", ordered_json::array({a.origin, a.toward})},
                      {"offset", pose_json(a.offset)}});
  j["attach"] = attach;
  return j;
}

}  // namespace

Reconfigurable parse_scene(const std::string& json_text, const fs::path& base_dir, const std::string& file_label,
                           const SceneLoadOptions& options) {
  nlohmann::json document;
  try {
    document = reconfig::detail::parse_strict_json(json_text);
  } catch (const InputError& error) {
    throw error.in_file(file_label);
  }
  try {
    return read_scene(JsonCursor(document, ""), base_dir, options);
  } catch (const InputError& error) {
    throw error.in_file(file_label);
  }
}

Reconfigurable load_scene(const fs::path& file, const SceneLoadOptions& options) {
  return parse_scene(read_input_file(file), fs::absolute(file).parent_path(), file.string(), options);
}

std::string scene_to_json(const Reconfigurable& scene, const fs::path& base_dir) {
  ordered_json root;
  root["format"] = kFormat;
  root["version"] = kVersion;
  root["units"] = scene.units;
  if (!scene.ground) root["ground"] = false;
  root["parts"] = ordered_json::array();
  for (const Part& part : scene.parts) root["parts"].push_back(part_json(part, base_dir));
  root["states"] = ordered_json::array();
  for (const State& state : scene.states) {
    ordered_json poses = ordered_json::object();
    for (const auto& [name, pose] : state.poses) poses[name] = pose_json(pose);
    root["states"].push_back({{"name", state.name}, {"poses", poses}});
  }
  root["transitions"] = ordered_json::array();
  for (const Transition& transition : scene.transitions) {
    ordered_json tracks = ordered_json::object();
    for (const auto& [name, track] : transition.tracks)
      if (!transition.linkage || !transition.linkage->drives(name)) tracks[name] = track_json(track);
    ordered_json entry = {{"name", transition.name},
                          {"from", transition.from},
                          {"to", transition.to},
                          {"bidirectional", transition.bidirectional},
                          {"tracks", tracks}};
    if (transition.linkage) entry["linkage"] = drive_json(*transition.linkage, base_dir);
    root["transitions"].push_back(entry);
  }
  if (!scene.collision.empty()) root["collision"] = collision_settings_json(scene.collision);
  if (scene.view)
    root["view"] = {{"target", vector_json(scene.view->target)},
                    {"distance", scene.view->distance},
                    {"yaw_degrees", scene.view->yaw_degrees},
                    {"pitch_degrees", scene.view->pitch_degrees}};
  return root.dump(2) + "\n";
}

void write_edited_meshes(Reconfigurable& scene, const fs::path& mesh_dir) {
  for (Part& part : scene.parts) {
    if (!std::holds_alternative<EditedMesh>(part.source)) continue;
    std::string stem = part.name;
    for (char& ch : stem)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
    const fs::path mesh_file = mesh_dir / (stem + ".obj");
    fs::create_directories(mesh_dir);
    geometry::save_obj(mesh_file, part.mesh);
    part.source = MeshFile{mesh_file};
  }
}

void save_scene(Reconfigurable& scene, const fs::path& file) {
  const fs::path base_dir = fs::absolute(file).parent_path();
  write_edited_meshes(scene, base_dir / "meshes");
  const std::string text = scene_to_json(scene, base_dir);
  write_atomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace reconfig::scene
