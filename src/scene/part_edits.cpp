// Edits of the list of parts: add, rename, recolor, duplicate, delete.

#include "reconfig/scene/part_edits.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

#include "scene/detail/list_edit.h"

namespace reconfig::scene {
namespace {

using detail::refuse;

void check_color(const std::optional<Eigen::Vector3d>& color) {
  if (color && (!color->allFinite() || (color->array() < 0).any() || (color->array() > 1).any()))
    refuse("color components must lie in [0, 1]");
}

/// The names of the transitions that give `part` a track, for a refusal.
std::vector<std::string> transitions_moving(const Reconfigurable& scene, const std::string& part) {
  std::vector<std::string> names;
  for (const Transition& transition : scene.transitions)
    if (transition.tracks.count(part)) names.push_back("\"" + transition.name + "\"");
  return names;
}

void check_primitive(const PartSource& source) {
  const auto positive = [](double size) { return std::isfinite(size) && size > 0; };
  bool ok = false;
  if (const auto* box = std::get_if<BoxPrimitive>(&source))
    ok = positive(box->size.x()) && positive(box->size.y()) && positive(box->size.z());
  else if (const auto* cylinder = std::get_if<CylinderPrimitive>(&source))
    ok = positive(cylinder->radius) && positive(cylinder->height);
  else if (const auto* sphere = std::get_if<SpherePrimitive>(&source))
    ok = positive(sphere->radius);
  else
    refuse("a primitive is a box, a cylinder or a sphere");
  if (!ok) refuse("a primitive's sizes must be positive");
}

void append_part(Reconfigurable& scene, const std::string& name, const geometry::Mesh& mesh, const PartSource& source,
                 const std::optional<Eigen::Vector3d>& color) {
  detail::check_new_name(scene, "part", name);
  if (mesh.empty()) refuse(fmt::format("part \"{}\": the mesh has no triangles", name));
  check_color(color);
  Part part;
  part.name = name;
  part.source = source;
  part.color = color;
  part.mesh = mesh;
  part.center = part_center(mesh);
  if (!part.center.allFinite()) part.center = mesh.V.colwise().mean().transpose();  // an open mesh has no volume
  scene.parts.push_back(std::move(part));
}

}  // namespace

std::unique_ptr<Command> add_part(std::string name, geometry::Mesh mesh, PartSource source,
                                  std::optional<Eigen::Vector3d> color) {
  std::string label = fmt::format("add part {}", name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    append_part(scene, name, mesh, source, color);
    return detail::structure_changed();
  });
}

std::unique_ptr<Command> add_primitive_part(std::string name, PartSource primitive, std::optional<Eigen::Vector3d> color) {
  std::string label = fmt::format("add part {}", name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    check_primitive(primitive);
    append_part(scene, name, Part::primitive_mesh(primitive), primitive, color);
    return detail::structure_changed();
  });
}

std::unique_ptr<Command> rename_part(std::string part, std::string new_name) {
  std::string label = fmt::format("rename part {} to {}", part, new_name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::part_index(scene, part);
    detail::check_new_name(scene, "part", new_name);
    scene.parts[index].name = new_name;
    const auto rename_key = [&](auto& map) {
      if (auto node = map.extract(part)) {
        node.key() = new_name;
        map.insert(std::move(node));
      }
    };
    for (State& state : scene.states) rename_key(state.poses);
    for (Transition& transition : scene.transitions) {
      rename_key(transition.tracks);
      if (!transition.linkage) continue;
      rename_key(transition.linkage->compiled);
      for (LinkageAttachment& attachment : transition.linkage->attach)
        if (attachment.part == part) attachment.part = new_name;
    }
    return DirtySet{};  // the collision engine knows parts by index
  });
}

std::unique_ptr<Command> recolor_part(std::string part, std::optional<Eigen::Vector3d> color) {
  std::string label = fmt::format("recolor {}", part);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::part_index(scene, part);
    check_color(color);
    scene.parts[index].color = color;
    return DirtySet{};
  });
}

std::unique_ptr<Command> duplicate_part(std::string part, std::string new_name) {
  std::string label = fmt::format("duplicate {} as {}", part, new_name);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::part_index(scene, part);
    detail::check_new_name(scene, "part", new_name);
    Part copy = scene.parts[index];
    copy.name = new_name;
    scene.parts.push_back(std::move(copy));
    for (State& state : scene.states)
      if (const auto it = state.poses.find(part); it != state.poses.end()) state.poses[new_name] = it->second;
    for (Transition& transition : scene.transitions) {
      const auto it = transition.tracks.find(part);
      const bool driven = transition.linkage && transition.linkage->drives(part);
      if (it != transition.tracks.end() && !driven) transition.tracks[new_name] = it->second;
    }
    return detail::structure_changed();
  });
}

std::unique_ptr<Command> delete_part(std::string part, bool with_tracks) {
  std::string label = fmt::format("delete part {}", part);
  return detail::list_edit(std::move(label), [=](Reconfigurable& scene) {
    const int index = detail::part_index(scene, part);
    for (const Transition& transition : scene.transitions)
      if (transition.linkage && transition.linkage->drives(part))
        refuse(fmt::format("part \"{}\" is driven by the linkage of transition \"{}\": detach it there first", part,
                           transition.name));
    const std::vector<std::string> moving = transitions_moving(scene, part);
    if (!moving.empty() && !with_tracks)
      refuse(fmt::format("part \"{}\" moves in {} {}: delete it with its keys, or remove them first", part,
                         moving.size() == 1 ? "transition" : "transitions", fmt::join(moving, ", ")));
    scene.parts.erase(scene.parts.begin() + index);
    for (State& state : scene.states) state.poses.erase(part);
    for (Transition& transition : scene.transitions) transition.tracks.erase(part);
    return detail::structure_changed();
  });
}

}  // namespace reconfig::scene
