// Authoring a design in the studio: a new design, importing meshes as parts, replacing a
// part's mesh, adding states from the view and transitions between states. Everything is a
// scene command (part_edits.h, state_edits.h, transition_edits.h), so it is undoable and
// the collision service re-detects what it dirtied; refusals go to the status line and leave
// the design untouched.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <system_error>

#include "reconfig/geometry/load_mesh.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/scene/part_edits.h"
#include "reconfig/scene/state_edits.h"
#include "resolve_panel.h"
#include "studio.h"

namespace reconfig::studio {

namespace fs = std::filesystem;

namespace {

/// Colors for imported parts, in turn: distinguishable, not too saturated.
constexpr std::array<std::array<double, 3>, 8> kPalette{{{0.72, 0.52, 0.32},
                                                         {0.35, 0.45, 0.62},
                                                         {0.45, 0.62, 0.38},
                                                         {0.70, 0.38, 0.36},
                                                         {0.55, 0.45, 0.65},
                                                         {0.80, 0.68, 0.35},
                                                         {0.38, 0.60, 0.62},
                                                         {0.60, 0.60, 0.58}}};

Eigen::Vector3d palette_color(std::size_t k) {
  const auto& c = kPalette[k % kPalette.size()];
  return {c[0], c[1], c[2]};
}

/// `wanted` with characters other than letters, digits, '-' and '_' made '_', then made
/// unique among `taken` by a suffix "_2", "_3"…; the result is added to `taken`.
std::string unique_name(std::string wanted, std::set<std::string>& taken) {
  for (char& c : wanted)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  if (wanted.empty()) wanted = "part";
  std::string name = wanted;
  for (int k = 2; taken.count(name); ++k) name = fmt::format("{}_{}", wanted, k);
  taken.insert(name);
  return name;
}

/// The reason a mesh cannot be a part (the scene file would refuse it on loading), or "".
std::string unusable(const geometry::MeshReport& report) {
  if (!report.is_manifold() || report.non_finite_vertices.any() || report.out_of_range_faces.any())
    return "unusable mesh: " + report.summary();
  return "";
}

/// What a designer should know about a usable mesh that is no valid solid (open,
/// self-intersecting, inside out), or "".
std::string warning(const geometry::MeshReport& report) { return report.is_valid_solid() ? "" : report.summary(); }

geometry::MeshReport check_for_import(const geometry::Mesh& mesh) {
  geometry::MeshCheckOptions options;
  options.max_self_intersection_pairs = 0;  // whether there is any is enough here
  return geometry::check_mesh(mesh, options);
}

}  // namespace

bool Studio::new_design(const fs::path& file) {
  if (refuse_while_linkage_unsaved(file)) return false;
  std::error_code error;
  if (file.empty()) {
    set_status("a new design needs the file it will be saved as", true);
    return false;
  }
  if (fs::exists(file, error)) {
    set_status(fmt::format("{} exists already: open it, or choose another file for the new design", file.string()),
               true);
    return false;
  }
  const fs::path absolute = fs::absolute(file).lexically_normal();
  fs::create_directories(absolute.parent_path(), error);
  if (error) {
    set_status(fmt::format("cannot create the folder {}: {}", absolute.parent_path().string(), error.message()), true);
    return false;
  }
  scene::Reconfigurable scene;
  scene.states.push_back({"start", {}});
  document_ = std::make_unique<Document>(std::move(scene), absolute, options_.collisions);
  reset_view_for_new_document();
  set_status(fmt::format("new design {}: import meshes (File > Import mesh...) or add primitives (Design)",
                         absolute.filename().string()));
  return true;
}

bool Studio::import_meshes(const std::vector<fs::path>& files) {
  if (!document_) {
    set_status("start a design (File > New) or open one before importing meshes", true);
    return false;
  }
  if (files.empty()) {
    set_status("no mesh file to import", true);
    return false;
  }
  const scene::Reconfigurable& scene = document_->scene();
  std::set<std::string> taken;
  for (const scene::Part& part : scene.parts) taken.insert(part.name);
  std::vector<std::unique_ptr<scene::Command>> steps;
  std::vector<std::string> names, warnings;
  for (const fs::path& file : files) {
    std::vector<geometry::NamedMesh> meshes;
    try {
      meshes = geometry::load_mesh_parts(file, {options_.load.allow_outside_paths});
    } catch (const std::exception& error) {
      set_status(fmt::format("cannot import {}: {}", file.string(), error.what()), true);
      return false;
    }
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const bool alone = meshes.size() == 1;
      const std::string stem = file.stem().string();
      std::string name = unique_name(alone || meshes[m].name.empty() ? (alone ? stem : fmt::format("{}_{}", stem, m + 1))
                                                                     : meshes[m].name,
                                     taken);
      const geometry::MeshReport report = check_for_import(meshes[m].mesh);
      if (const std::string problem = unusable(report); !problem.empty()) {
        set_status(fmt::format("cannot import {}: {}", file.string(), problem), true);
        return false;
      }
      if (const std::string note = warning(report); !note.empty()) warnings.push_back(name + ": " + note);
      // One mesh of several has no file of its own: saving writes it beside the design.
      const scene::PartSource source =
          alone ? scene::PartSource{scene::MeshFile{fs::absolute(file).lexically_normal()}} : scene::EditedMesh{};
      steps.push_back(scene::add_part(name, std::move(meshes[m].mesh), source,
                                      palette_color(scene.parts.size() + names.size())));
      names.push_back(name);
    }
  }
  const std::string label =
      names.size() == 1 ? fmt::format("import {}", names[0]) : fmt::format("import {} parts", names.size());
  auto command = steps.size() == 1 ? std::move(steps[0]) : scene::command_sequence(label, std::move(steps));
  if (!execute(std::move(command))) return false;
  select_part(document_->scene().find_part(names.back()));
  std::string message = fmt::format("imported {}", fmt::join(names, ", "));
  if (!warnings.empty()) message += fmt::format(" — warning: {}", fmt::join(warnings, "; "));
  set_status(message, !warnings.empty());
  if (document_->scene().parts.size() == names.size()) frame_all();  // the first parts: show them
  return true;
}

bool Studio::replace_part_mesh_from(int part, const fs::path& file) {
  if (!document_ || part < 0 || part >= static_cast<int>(document_->scene().parts.size())) {
    set_status("select the part whose mesh to replace", true);
    return false;
  }
  geometry::Mesh mesh;
  try {
    mesh = geometry::load_mesh(file, {options_.load.allow_outside_paths});
  } catch (const std::exception& error) {
    set_status(fmt::format("cannot replace the mesh: {}", error.what()), true);
    return false;
  }
  const geometry::MeshReport report = check_for_import(mesh);
  if (const std::string problem = unusable(report); !problem.empty()) {
    set_status(fmt::format("cannot replace the mesh with {}: {}", file.string(), problem), true);
    return false;
  }
  const std::string name = document_->scene().parts[part].name;
  if (!execute(scene::replace_part_mesh(name, std::move(mesh), scene::MeshFile{fs::absolute(file).lexically_normal()})))
    return false;
  if (const std::string note = warning(report); !note.empty())
    set_status(fmt::format("replaced the mesh of {} — warning: {}", name, note), true);
  return true;
}

bool Studio::add_state_from_view(const std::string& name) {
  if (!document_) return false;
  const scene::Reconfigurable& scene = document_->scene();
  if (!execute(scene::add_state(name, scene::current_poses(scene, active_transition_, active_state_, time_))))
    return false;
  show_state(document_->scene().find_state(name));
  return true;
}

void Studio::show_state(int state) {
  if (!document_ || state < 0 || state >= static_cast<int>(document_->scene().states.size())) return;
  active_transition_ = -1;
  active_state_ = state;
  playing_ = false;
  selected_key_.reset();
}

bool Studio::add_transition_between(int from, int to, scene::Choreography choreography, std::string name) {
  if (!document_) return false;
  const scene::Reconfigurable& scene = document_->scene();
  const int states = static_cast<int>(scene.states.size());
  if (from < 0 || from >= states || to < 0 || to >= states) {
    set_status("a transition goes from a state to a state", true);
    return false;
  }
  if (name.empty()) {
    std::set<std::string> taken;
    for (const scene::Transition& transition : scene.transitions) taken.insert(transition.name);
    name = unique_name(scene.states[from].name + "_to_" + scene.states[to].name, taken);
  }
  if (!execute(scene::add_transition(name, scene.states[from].name, scene.states[to].name, choreography))) return false;
  open_transition(document_->scene().find_transition(name));
  set_time(0);
  return true;
}

Studio::ViewNames Studio::remember_view() const {
  ViewNames names;
  if (!document_) return names;
  const scene::Reconfigurable& scene = document_->scene();
  for (int t : open_transitions_) names.open_transitions.push_back(scene.transitions[t].name);
  if (active_transition_ >= 0) names.active_transition = scene.transitions[active_transition_].name;
  if (active_state_ < static_cast<int>(scene.states.size())) names.state = scene.states[active_state_].name;
  if (selected_part_ >= 0) names.part = scene.parts[selected_part_].name;
  names.counts = {scene.parts.size(), scene.states.size(), scene.transitions.size()};
  names.open_indices = open_transitions_;
  names.active_index = active_transition_;
  names.state_index = active_state_;
  names.part_index = selected_part_;
  return names;
}

void Studio::restore_view(const ViewNames& names) {
  if (!document_) return;
  const scene::Reconfigurable& scene = document_->scene();
  // By name; else (a rename: the list kept its length) the same index; else nothing.
  const auto find = [](int found, int index, std::size_t count, std::size_t old_count) {
    return found >= 0 ? found : count == old_count && index >= 0 && index < static_cast<int>(count) ? index : -1;
  };
  const std::size_t transitions = scene.transitions.size();
  std::vector<int> open;
  for (std::size_t k = 0; k < names.open_transitions.size(); ++k) {
    const int t = find(scene.find_transition(names.open_transitions[k]), names.open_indices[k], transitions,
                       names.counts[2]);
    if (t >= 0 && std::find(open.begin(), open.end(), t) == open.end()) open.push_back(t);
  }
  const int active = names.active_index < 0 ? -1
                                            : find(scene.find_transition(names.active_transition), names.active_index,
                                                   transitions, names.counts[2]);
  const bool lost_transition = names.active_index >= 0 && active < 0;
  open_transitions_ = open;
  active_transition_ = active >= 0 ? active : lost_transition && !open.empty() ? open.back() : -1;
  active_state_ = std::max(0, find(scene.find_state(names.state), names.state_index, scene.states.size(), names.counts[1]));
  if (active_state_ >= static_cast<int>(scene.states.size())) active_state_ = 0;
  const int part = names.part_index < 0 ? -1
                                        : find(scene.find_part(names.part), names.part_index, scene.parts.size(),
                                               names.counts[0]);
  if (part != selected_part_ || active_transition_ != names.active_index) selected_key_.reset();
  selected_part_ = part;
  if (active_transition_ < 0) playing_ = false;
  // A hint and the picture-in-picture name parts and transitions by index: after the lists
  // changed they may name others, or none.
  const std::array<std::size_t, 3> counts{scene.parts.size(), scene.states.size(), scene.transitions.size()};
  if (counts != names.counts) {
    resolve().forget_hint();
    pip_.close();
  }
}

}  // namespace reconfig::studio
