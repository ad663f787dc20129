#include "reconfig/linkage/linkage_file.h"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "common/detail/strict_json.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/read_input_file.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/linkage/joint_order.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {
namespace {

using nlohmann::json;

struct Parser {
  std::string file;

  [[noreturn]] void fail(const std::string& location, const std::string& message) const {
    throw InputError(file, location, message);
  }

  const json& member(const json& object, const std::string& key, const std::string& location) const {
    auto it = object.find(key);
    if (it == object.end()) fail(location, "missing \"" + key + "\"");
    return *it;
  }

  std::string string_value(const json& value, const std::string& location) const {
    if (!value.is_string()) fail(location, "expected a string");
    return value.get<std::string>();
  }

  /// A name is printed by the tools: no control characters (terminal escape sequences).
  std::string name_value(const json& value, const std::string& location) const {
    std::string name = string_value(value, location);
    for (const char c : name)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) fail(location, "a name must not contain control characters");
    return name;
  }

  Eigen::Vector2d point(const json& value, const std::string& location) const {
    if (!value.is_array() || value.size() != 2) fail(location, "expected a point [x, y]");
    Eigen::Vector2d p;
    for (int c = 0; c < 2; ++c) {
      if (!value[c].is_number()) fail(location + "[" + std::to_string(c) + "]", "expected a number");
      p[c] = value[c].get<double>();
      // Squared lengths must stay finite and meaningful: keep coordinates below 1e12.
      if (!(std::abs(p[c]) <= 1e12)) fail(location + "[" + std::to_string(c) + "]", "coordinate out of range (|x| > 1e12)");
    }
    return p;
  }

  int joint_ref(const Linkage& linkage, const json& value, const std::string& location) const {
    const std::string name = string_value(value, location);
    const int index = linkage.find_joint(name);
    if (index < 0) fail(location, "unknown joint \"" + name + "\"");
    return index;
  }

  Linkage parse(const std::string& text) const {
    json doc;
    try {
      doc = reconfig::detail::parse_strict_json(text);
    } catch (const InputError& error) {
      fail(error.location(), error.message());
    }
    if (!doc.is_object()) fail("", "expected a JSON object");
    if (string_value(member(doc, "format", ""), "format") != "reconfig-linkage")
      fail("format", "expected \"reconfig-linkage\"");
    const json& version = member(doc, "version", "");
    if (!version.is_number_integer() || version != 1)  // as a number: 2^32 + 1 is no 1
      fail("version", "unsupported version: " + reconfig::detail::describe_json(version) + " (expected 1)");

    Linkage linkage;
    const json& joints = member(doc, "joints", "");
    if (!joints.is_array() || joints.empty()) fail("joints", "expected a non-empty array of joints");
    std::set<std::string> names;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const std::string at = "joints[" + std::to_string(j) + "]";
      const json& entry = joints[j];
      if (!entry.is_object()) fail(at, "expected an object");
      Joint joint;
      joint.name = name_value(member(entry, "name", at), at + ".name");
      if (joint.name.empty()) fail(at + ".name", "empty joint name");
      if (!names.insert(joint.name).second) fail(at + ".name", "duplicate joint name \"" + joint.name + "\"");
      joint.position = point(member(entry, "position", at), at + ".position");
      if (auto it = entry.find("fixed"); it != entry.end()) {
        if (!it->is_boolean()) fail(at + ".fixed", "expected true or false");
        joint.fixed = it->get<bool>();
      }
      linkage.joints.push_back(joint);
    }

    const json& links = member(doc, "links", "");
    if (!links.is_array() || links.empty()) fail("links", "expected a non-empty array of links");
    for (std::size_t l = 0; l < links.size(); ++l) {
      const std::string at = "links[" + std::to_string(l) + "]";
      if (!links[l].is_array() || links[l].size() < 2) fail(at, "a link carries two or more joints");
      std::vector<int> link;
      for (std::size_t m = 0; m < links[l].size(); ++m) {
        const std::string at_m = at + "[" + std::to_string(m) + "]";
        const int joint = joint_ref(linkage, links[l][m], at_m);
        for (int other : link) {
          if (other == joint) fail(at_m, "joint \"" + linkage.joints[joint].name + "\" appears twice on the link");
          if ((linkage.joints[other].position - linkage.joints[joint].position).norm() <= 1e-12)
            fail(at_m, "joints \"" + linkage.joints[other].name + "\" and \"" + linkage.joints[joint].name +
                           "\" of one link are at the same position");
        }
        link.push_back(joint);
      }
      linkage.links.push_back(link);
    }

    const auto links_of = linkage.links_of_joints();
    for (std::size_t j = 0; j < linkage.joints.size(); ++j)
      if (!linkage.joints[j].fixed && links_of[j].empty())
        fail("joints[" + std::to_string(j) + "]", "joint \"" + linkage.joints[j].name + "\" is on no link and not fixed");

    const json& motor = member(doc, "motor", "");
    if (!motor.is_object()) fail("motor", "expected an object {\"center\", \"joint\"}");
    linkage.motor.center = joint_ref(linkage, member(motor, "center", "motor"), "motor.center");
    linkage.motor.joint = joint_ref(linkage, member(motor, "joint", "motor"), "motor.joint");
    if (!linkage.joints[linkage.motor.center].fixed) fail("motor.center", "the motor center must be a fixed joint");
    if (linkage.motor.joint == linkage.motor.center) fail("motor.joint", "the motor joint must differ from its center");
    if (linkage.joints[linkage.motor.joint].fixed) fail("motor.joint", "the motor joint must not be fixed");
    bool crank = false;
    for (int l : links_of[linkage.motor.joint])
      for (int j : linkage.links[l]) crank = crank || j == linkage.motor.center;
    if (!crank) fail("motor", "no link (crank) carries both the motor center and the motor joint");

    if (auto it = doc.find("tracking_points"); it != doc.end()) {
      if (!it->is_array()) fail("tracking_points", "expected an array");
      for (std::size_t t = 0; t < it->size(); ++t) {
        const std::string at = "tracking_points[" + std::to_string(t) + "]";
        const json& entry = (*it)[t];
        if (!entry.is_object()) fail(at, "expected an object {\"name\", \"joint\"}");
        TrackingPoint point;
        point.name = name_value(member(entry, "name", at), at + ".name");
        point.joint = joint_ref(linkage, member(entry, "joint", at), at + ".joint");
        linkage.tracking_points.push_back(point);
      }
    }
    return linkage;
  }
};

// The rules keep the distances they use; a link whose other distances would have to
// change as the motor turns makes the linkage over-constrained (it would lock). Checked on
// 24 motor angles over the motion range.
void check_not_over_constrained(const SymbolicKinematics& kinematics) {
  const Linkage& linkage = kinematics.linkage();
  const MotionRange range = motion_range(kinematics);
  const Eigen::Matrix2Xd X0 = linkage.initial_positions();
  double scale = 1;
  for (const Joint& joint : linkage.joints) scale = std::max(scale, joint.position.cwiseAbs().maxCoeff());
  Eigen::Matrix2Xd X;
  for (int s = 0; s < 24; ++s) {
    const double angle = range.lower + (range.upper - range.lower) * (s + 0.5) / 24;
    if (!kinematics.solve(angle, X)) continue;  // not reached: the range says it is
    for (std::size_t l = 0; l < linkage.links.size(); ++l) {
      const auto& link = linkage.links[l];
      for (std::size_t a = 0; a < link.size(); ++a)
        for (std::size_t b = a + 1; b < link.size(); ++b) {
          const double before = (X0.col(link[a]) - X0.col(link[b])).norm();
          const double after = (X.col(link[a]) - X.col(link[b])).norm();
          if (std::abs(after - before) > 1e-7 * scale)
            throw InputError("", "links[" + std::to_string(l) + "]",
                             "the linkage is over-constrained: joints \"" + linkage.joints[link[a]].name + "\" and \"" +
                                 linkage.joints[link[b]].name + "\" of this link would have to move from " +
                                 std::to_string(before) + " to " + std::to_string(after) +
                                 " apart as the motor turns (the mechanism locks)");
        }
    }
  }
  kinematics.reset_continuation();
}

}  // namespace

Linkage parse_linkage(const std::string& text, const std::string& file) { return Parser{file}.parse(text); }

void check_linkage(const Linkage& linkage) {
  const JointOrder order = order_joints(linkage);
  const SymbolicKinematics kinematics(linkage, order);  // checks the initial configuration
  check_not_over_constrained(kinematics);
}

Linkage read_linkage(const std::filesystem::path& path) {
  Linkage linkage = parse_linkage(read_input_file(path), path.string());
  try {
    check_linkage(linkage);
  } catch (const InputError& error) {
    throw error.in_file(path.string());
  }
  return linkage;
}

std::string linkage_to_json(const Linkage& linkage) {
  json doc;
  doc["format"] = "reconfig-linkage";
  doc["version"] = 1;
  json joints = json::array();
  for (const Joint& joint : linkage.joints) {
    json entry = {{"name", joint.name}, {"position", {joint.position.x(), joint.position.y()}}};
    if (joint.fixed) entry["fixed"] = true;
    joints.push_back(entry);
  }
  doc["joints"] = joints;
  json links = json::array();
  for (const auto& link : linkage.links) {
    json names = json::array();
    for (int j : link) names.push_back(linkage.joints[j].name);
    links.push_back(names);
  }
  doc["links"] = links;
  doc["motor"] = {{"center", linkage.joints[linkage.motor.center].name},
                  {"joint", linkage.joints[linkage.motor.joint].name}};
  if (!linkage.tracking_points.empty()) {
    json points = json::array();
    for (const TrackingPoint& point : linkage.tracking_points)
      points.push_back({{"name", point.name}, {"joint", linkage.joints[point.joint].name}});
    doc["tracking_points"] = points;
  }
  return doc.dump(2);
}

void write_linkage(const Linkage& linkage, const std::filesystem::path& path) {
  const std::string text = linkage_to_json(linkage) + "\n";
  write_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace reconfig::linkage
