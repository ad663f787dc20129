// reconfig info SCENE — what a scene contains: parts (triangles, mesh status), states, transitions.

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "command.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/mesh_check.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {
namespace {

struct InfoOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  bool json = false;
};

std::string source_text(const scene::PartSource& source) {
  if (const auto* file = std::get_if<scene::MeshFile>(&source)) return file->path.filename().string();
  if (const auto* box = std::get_if<scene::BoxPrimitive>(&source))
    return fmt::format("box {:g}×{:g}×{:g}", box->size.x(), box->size.y(), box->size.z());
  if (const auto* cylinder = std::get_if<scene::CylinderPrimitive>(&source))
    return fmt::format("cylinder r={:g} h={:g}", cylinder->radius, cylinder->height);
  if (const auto* sphere = std::get_if<scene::SpherePrimitive>(&source)) return fmt::format("sphere r={:g}", sphere->radius);
  return "edited";
}

std::string track_text(const scene::Track& track) {
  if (const auto* screw = std::get_if<scene::ScrewPosesTrack>(&track))
    return fmt::format("screw, {} key poses", screw->poses.size());
  const auto& keyed = std::get<scene::KeyframedTrack>(track);
  return fmt::format("{} translation / {} rotation keys", keyed.translation.size(), keyed.rotation.size());
}

int run_info(const InfoOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  nlohmann::ordered_json json;
  json["parts"] = nlohmann::ordered_json::array();
  if (!options.json)
    fmt::print("{}: {} parts, {} states, {} transitions (units: {})\n\nparts:\n", options.scene, scene.parts.size(),
               scene.states.size(), scene.transitions.size(), scene.units);
  bool all_valid = true;
  for (const scene::Part& part : scene.parts) {
    const geometry::MeshReport report = geometry::check_mesh(part.mesh);
    const geometry::MassProperties mass = geometry::mass_properties(part.mesh);
    all_valid = all_valid && report.is_valid_solid();
    json["parts"].push_back({{"name", part.name},
                             {"source", source_text(part.source)},
                             {"triangles", part.mesh.face_count()},
                             {"vertices", part.mesh.vertex_count()},
                             {"volume", mass.volume},
                             {"valid_solid", report.is_valid_solid()},
                             {"mesh_status", report.summary()}});
    if (!options.json)
      fmt::print("  {:<16} {:<28} {:>8} triangles  volume {:<10.4g} {}{}\n", part.name, source_text(part.source),
                 part.mesh.face_count(), mass.volume, report.is_valid_solid() ? "" : "WARNING: ", report.summary());
  }
  json["states"] = nlohmann::ordered_json::array();
  if (!options.json) fmt::print("\nstates:\n");
  for (const scene::State& state : scene.states) {
    json["states"].push_back({{"name", state.name}, {"posed_parts", state.poses.size()}});
    if (!options.json) fmt::print("  {:<16} {} parts posed\n", state.name, state.poses.size());
  }
  json["transitions"] = nlohmann::ordered_json::array();
  if (!options.json) fmt::print("\ntransitions:\n");
  for (const scene::Transition& transition : scene.transitions) {
    nlohmann::ordered_json tracks = nlohmann::ordered_json::object();
    for (const auto& [part, track] : transition.tracks) tracks[part] = track_text(track);
    json["transitions"].push_back({{"name", transition.name},
                                   {"from", transition.from},
                                   {"to", transition.to},
                                   {"bidirectional", transition.bidirectional},
                                   {"tracks", tracks}});
    if (options.json) continue;
    fmt::print("  {:<16} {} → {}{}\n", transition.name, transition.from, transition.to,
               transition.bidirectional ? " (bidirectional)" : "");
    for (const auto& [part, track] : transition.tracks) fmt::print("    {:<14} {}\n", part, track_text(track));
  }
  if (options.json) fmt::print("{}\n", json.dump(2));
  return kExitOk;
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* command = app.add_subcommand("info", "Parts (triangles, mesh check), states and transitions of a scene");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  add_allow_outside_paths_flag(*command, options->load);
  command->add_flag("--json", options->json, "Print as JSON");
  command->callback([options, &exit_code] { exit_code = run_info(*options); });
}

}  // namespace reconfig::cli
