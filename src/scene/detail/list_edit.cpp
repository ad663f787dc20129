#include "scene/detail/list_edit.h"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "reconfig/common/input_error.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::scene::detail {

void refuse(const std::string& message) { throw InputError("", "", message); }

void check_new_name(const Reconfigurable& scene, const std::string& kind, const std::string& name) {
  if (name.empty()) refuse(fmt::format("a {} needs a name", kind));
  const bool taken = kind == "part"    ? scene.find_part(name) >= 0
                     : kind == "state" ? scene.find_state(name) >= 0
                                       : scene.find_transition(name) >= 0;
  if (taken) refuse(fmt::format("there is already a {} named \"{}\"", kind, name));
}

int part_index(const Reconfigurable& scene, const std::string& name) {
  const int index = scene.find_part(name);
  if (index < 0) refuse(fmt::format("unknown part \"{}\"", name));
  return index;
}

int state_index(const Reconfigurable& scene, const std::string& name) {
  const int index = scene.find_state(name);
  if (index < 0) refuse(fmt::format("unknown state \"{}\"", name));
  return index;
}

int transition_index(const Reconfigurable& scene, const std::string& name) {
  const int index = scene.find_transition(name);
  if (index < 0) refuse(fmt::format("unknown transition \"{}\"", name));
  return index;
}

DirtySet structure_changed() {
  DirtySet dirty;
  dirty.structure_changed = true;
  return dirty;
}

DirtySet transition_appended(const Reconfigurable& scene) {
  DirtySet dirty;
  dirty.added_transitions.push_back(static_cast<int>(scene.transitions.size()) - 1);
  return dirty;
}

namespace {

/// A part without its mesh.
struct PartHeader {
  std::string name;
  PartSource source;
  std::optional<Eigen::Vector3d> color;
  Eigen::Vector3d center;
};

/// The lists of a design, with the whole parts (meshes too) that the other side of the edit
/// lacks (added, removed or renamed ones).
struct Lists {
  std::vector<PartHeader> parts;
  std::vector<State> states;
  std::vector<Transition> transitions;
  std::map<std::string, Part> only_here;
};

Lists capture(const Reconfigurable& scene) {
  Lists lists;
  for (const Part& part : scene.parts) lists.parts.push_back({part.name, part.source, part.color, part.center});
  lists.states = scene.states;
  lists.transitions = scene.transitions;
  return lists;
}

/// Keeps in `lists` the parts of `parts` whose names `other` lacks.
void keep_parts_missing_from(Lists& lists, std::vector<Part>& parts, const Lists& other) {
  for (Part& part : parts) {
    bool shared = false;
    for (const PartHeader& header : other.parts) shared |= header.name == part.name;
    if (!shared) lists.only_here.emplace(part.name, std::move(part));
  }
}

/// Makes the lists of `scene` those of `lists`, reusing the meshes already in `scene`.
void restore(Reconfigurable& scene, const Lists& lists) {
  std::map<std::string, Part> pool;
  for (Part& part : scene.parts) pool.emplace(part.name, std::move(part));
  for (const auto& [name, part] : lists.only_here) pool.insert_or_assign(name, part);
  scene.parts.clear();
  for (const PartHeader& header : lists.parts) {
    Part part = std::move(pool.at(header.name));
    part.source = header.source;
    part.color = header.color;
    part.center = header.center;
    scene.parts.push_back(std::move(part));
  }
  scene.states = lists.states;
  scene.transitions = lists.transitions;
}

class ListEdit final : public Command {
 public:
  ListEdit(std::string label, ListMutation edit) : label_(std::move(label)), edit_(std::move(edit)) {}

  DirtySet apply(Reconfigurable& scene) override {
    if (after_) {
      restore(scene, *after_);
      return dirty_;
    }
    Lists before = capture(scene);
    std::vector<Part> parts_before = scene.parts;
    try {
      dirty_ = edit_(scene);
      validate_scene(scene);
    } catch (...) {
      before.only_here.clear();
      scene.parts = std::move(parts_before);
      restore(scene, before);
      throw;
    }
    Lists after = capture(scene);
    std::vector<Part> parts_after;
    for (const Part& part : scene.parts) {
      bool shared = false;
      for (const PartHeader& header : before.parts) shared |= header.name == part.name;
      if (!shared) parts_after.push_back(part);
    }
    keep_parts_missing_from(before, parts_before, after);
    keep_parts_missing_from(after, parts_after, before);
    before_ = std::move(before);
    after_ = std::move(after);
    return dirty_;
  }

  DirtySet revert(Reconfigurable& scene) override {
    restore(scene, *before_);
    // Taking appended transitions away again shifts nothing before them, but the detector of
    // each transition is known by its index: start over.
    return dirty_.added_transitions.empty() ? dirty_ : structure_changed();
  }

  std::string label() const override { return label_; }

 private:
  std::string label_;
  ListMutation edit_;
  std::optional<Lists> before_, after_;
  DirtySet dirty_;
};

}  // namespace

std::unique_ptr<Command> list_edit(std::string label, ListMutation edit) {
  return std::make_unique<ListEdit>(std::move(label), std::move(edit));
}

}  // namespace reconfig::scene::detail
