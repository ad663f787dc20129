// reconfig sweep SCENE --transition T --part B ... -o swept.obj|.stl — the volume a part sweeps;
// reconfig carve SCENE --transition T --part A --by B[,C...] ... -o OUT.json — carve A by it
// (docs/file-formats.md, "reconfig sweep" and "reconfig carve").

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "command.h"
#include "interrupt_guard.h"
#include "progress_bar.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/detector_settings.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/mass_properties.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/sweep/carve_part.h"
#include "screw_sweep.h"

namespace reconfig::cli {
namespace {

namespace fs = std::filesystem;

/// What both commands share: the scene, the motion, the grid.
struct SweepOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  std::string transition;
  std::string part;
  std::string relative_to;           // sweep: the frame (empty: world)
  std::string method = "sdf";        // sweep: sdf or screw
  std::vector<std::string> carvers;  // carve: --by
  double t0 = 0.0, t1 = 1.0;
  double grid = 0.0;
  double offset = 0.0;
  std::string output;
  bool json = false;
  bool stl = false;  // carve: also write the carved mesh as STL, for printing
};

int find_part(const scene::Reconfigurable& scene, const std::string& name, const std::string& file) {
  const int part = scene.find_part(name);
  if (part < 0) throw InputError(file, "", fmt::format("no part named \"{}\"", name));
  return part;
}

int find_transition(const scene::Reconfigurable& scene, const SweepOptions& options) {
  const int transition = scene.find_transition(options.transition);
  if (transition < 0) throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", options.transition));
  if (options.t0 > options.t1) throw InputError("", "", fmt::format("--from {} is after --to {}", options.t0, options.t1));
  return transition;
}

/// The sweep settings of the command line over `request` (the sweep's or a carve's defaults).
sweep::SweptVolumeRequest sweep_request(const SweepOptions& options, sweep::SweptVolumeRequest request = {}) {
  request.grid_step = options.grid;
  request.offset = options.offset;
  return request;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::ordered_json sweep_json(const sweep::SweptVolumeResult& result) {
  return {{"grid_step", result.grid_step},       {"grid_size", result.grid_size},
          {"time_samples", result.time_samples}, {"motion_error", result.motion_error},
          {"level", result.level},               {"margin", result.margin},
          {"verified", result.verified},
          {"band_voxels", result.active_voxels}, {"filled_cavities", result.filled_cavities},
          {"triangles", result.mesh.face_count()}, {"volume", geometry::mass_properties(result.mesh).volume}};
}

void save_mesh_file(const fs::path& path, const geometry::Mesh& mesh) {
  const std::string extension = path.extension().string();
  if (extension == ".stl") geometry::save_stl(path, mesh);
  else if (extension == ".obj") geometry::save_obj(path, mesh);
  else throw InputError(path.string(), "", "the output must be an .obj or .stl file");
}

/// `--method screw`: the envelope quads and the end poses, tolerance h (default: the part's box diagonal / 128).
int run_screw_sweep(const SweepOptions& options, const scene::Reconfigurable& scene, int part,
                    const sweep::RelativeMotion& motion) {
  const auto start = std::chrono::steady_clock::now();
  const geometry::Mesh& mesh = scene.parts[part].mesh;
  const double diagonal = (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  const double tolerance = options.grid > 0 ? options.grid : std::max(diagonal, 1e-9) / 128;
  const ScrewSweep result = screw_sweep(mesh, motion, tolerance);
  save_mesh_file(options.output, result.envelope.mesh);
  if (options.json) {
    nlohmann::ordered_json root = {{"transition", options.transition}, {"part", options.part},
                                   {"relative_to", options.relative_to.empty() ? nlohmann::ordered_json(nullptr)
                                                                               : nlohmann::ordered_json(options.relative_to)},
                                   {"from", options.t0}, {"to", options.t1}, {"method", "screw"},
                                   {"tolerance", tolerance}, {"screws", result.screws},
                                   {"motion_error", result.motion_error},
                                   {"silhouette_segments", result.envelope.silhouette_segments},
                                   {"steps", result.envelope.steps}, {"triangles", result.envelope.mesh.face_count()}};
    root["seconds"] = seconds_since(start);
    root["output"] = options.output;
    fmt::print("{}\n", root.dump(2));
  } else {
    fmt::print("{} swept over \"{}\" [{:g}, {:g}]: screw envelope of {} screws, {} silhouette segments, {} triangles; "
               "wrote {}\n",
               options.part, options.transition, options.t0, options.t1, result.screws,
               result.envelope.silhouette_segments, result.envelope.mesh.face_count(), options.output);
  }
  return kExitOk;
}

int run_sweep(const SweepOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  const int transition = find_transition(scene, options);
  const int part = find_part(scene, options.part, options.scene);
  const int frame = options.relative_to.empty() ? -1 : find_part(scene, options.relative_to, options.scene);
  if (frame == part) throw InputError("", "", "--relative-to names the swept part itself");
  const fs::path output = options.output;
  if (output.extension() != ".obj" && output.extension() != ".stl")
    throw InputError(options.output, "", "the output must be an .obj or .stl file");
  if (options.method == "screw")
    return run_screw_sweep(options, scene, part, sweep::relative_motion(scene, transition, part, frame, options.t0, options.t1));
  ProgressBar bar("sweeping", !options.json && stderr_is_terminal());
  const InterruptGuard interrupt;
  sweep::SweptVolumeRequest request = sweep_request(options);
  request.progress = interrupt.wrap(bar.callback());
  const auto start = std::chrono::steady_clock::now();
  const sweep::RelativeMotion motion = sweep::relative_motion(scene, transition, part, frame, options.t0, options.t1);
  const sweep::SweptVolumeResult result = sweep::swept_volume(scene.parts[part].mesh, motion, request);
  bar.finish();
  if (result.cancelled) {
    fmt::print(stderr, "reconfig: sweep cancelled (Ctrl+C): nothing written\n");
    return kExitInterrupted;
  }
  save_mesh_file(output, result.mesh);
  if (options.json) {
    nlohmann::ordered_json root = {{"transition", options.transition}, {"part", options.part},
                                   {"relative_to", options.relative_to.empty() ? nlohmann::ordered_json(nullptr)
                                                                               : nlohmann::ordered_json(options.relative_to)},
                                   {"from", options.t0}, {"to", options.t1}, {"offset", options.offset}};
    root.update(sweep_json(result));
    root["seconds"] = seconds_since(start);
    root["output"] = options.output;
    fmt::print("{}\n", root.dump(2));
  } else {
    fmt::print("{} swept over \"{}\" [{:g}, {:g}]: {} triangles, volume {:.6g}; grid {:.4g} ({}×{}×{}), {} poses, "
               "surface within ε + {:.3g} of the sweep; wrote {}\n",
               options.part, options.transition, options.t0, options.t1, result.mesh.face_count(),
               geometry::mass_properties(result.mesh).volume, result.grid_step, result.grid_size[0],
               result.grid_size[1], result.grid_size[2], result.time_samples, result.margin, options.output);
  }
  return kExitOk;
}

/// The intervals of `transition` in `scene` between `part` and one of `carvers`.
std::vector<collision::CollisionInterval> remaining_collisions(const scene::Reconfigurable& scene, int transition,
                                                              int part, const std::vector<int>& carvers) {
  collision::CollisionRequest detection;
  detection.detector = collision::with_settings({}, scene.collision);
  detection.transitions = {transition};
  std::vector<collision::CollisionInterval> left;
  for (const collision::CollisionInterval& ci : collision::detect_collisions(scene, detection).transitions.at(0).intervals) {
    const bool has_part = std::find(ci.parts.begin(), ci.parts.end(), part) != ci.parts.end();
    const bool has_carver = std::any_of(ci.parts.begin(), ci.parts.end(), [&](int p) {
      return std::find(carvers.begin(), carvers.end(), p) != carvers.end();
    });
    if (has_part && has_carver) left.push_back(ci);
  }
  return left;
}

std::string parts_text(const scene::Reconfigurable& scene, const std::vector<int>& parts) {
  std::string text;
  for (int p : parts) text += (text.empty() ? "" : " × ") + scene.parts[p].name;
  return text;
}

int run_carve(const SweepOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  sweep::CarveRequest request;
  request.transition = find_transition(scene, options);
  request.part = find_part(scene, options.part, options.scene);
  for (const std::string& name : options.carvers) {
    const int carver = find_part(scene, name, options.scene);
    if (carver == request.part) throw InputError("", "", fmt::format("--by names the carved part {} itself", name));
    request.carvers.push_back(carver);
  }
  request.t0 = options.t0;
  request.t1 = options.t1;
  request.sweep = sweep_request(options, sweep::carve_sweep_defaults());
  if (fs::path(options.output).extension() != ".json") throw InputError(options.output, "", "the output must be a .json scene");
  ProgressBar bar("carving", !options.json && stderr_is_terminal());
  const InterruptGuard interrupt;
  request.progress = interrupt.wrap(bar.callback());
  const auto start = std::chrono::steady_clock::now();
  const sweep::CarveResult carved = sweep::carve_part(scene, request);
  const double carve_seconds = seconds_since(start);
  bar.finish();
  if (carved.cancelled) {
    fmt::print(stderr, "reconfig: carve cancelled (Ctrl+C): nothing written\n");
    return kExitInterrupted;
  }
  if (!carved.ok()) {
    fmt::print(stderr, "reconfig: carve refused, nothing written: {}\n", carved.problem);
    return kExitCollisions;
  }
  scene::Reconfigurable result = scene;
  scene::Part& part = result.parts[request.part];
  part.mesh = carved.mesh;  // the pivot stays, so every pose places the part where it did
  std::string stem = part.name;
  for (char& ch : stem)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
  const fs::path mesh_file = fs::absolute(options.output).parent_path() / "meshes" / (stem + "-carved.obj");
  fs::create_directories(mesh_file.parent_path());
  geometry::save_obj(mesh_file, carved.mesh);
  if (options.stl) geometry::save_stl(fs::path(mesh_file).replace_extension(".stl"), carved.mesh);
  part.source = scene::MeshFile{mesh_file};
  scene::save_scene(result, options.output);
  const std::vector<collision::CollisionInterval> left =
      remaining_collisions(result, request.transition, request.part, request.carvers);
  if (options.json) {
    nlohmann::ordered_json sweeps = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < carved.sweeps.size(); ++i) {
      nlohmann::ordered_json entry = {{"by", options.carvers[i]}};
      entry.update(sweep_json(carved.sweeps[i]));
      sweeps.push_back(entry);
    }
    nlohmann::ordered_json still = nlohmann::ordered_json::array();
    for (const collision::CollisionInterval& ci : left) {
      nlohmann::ordered_json names = nlohmann::ordered_json::array();
      for (int p : ci.parts) names.push_back(result.parts[p].name);
      still.push_back({{"parts", names}, {"t0", ci.t0}, {"t1", ci.t1}});
    }
    const nlohmann::ordered_json root = {
        {"transition", options.transition}, {"part", options.part},         {"by", options.carvers},
        {"from", options.t0},               {"to", options.t1},             {"offset", options.offset},
        {"volume_before", carved.volume_before}, {"volume_after", carved.volume_after},
        {"triangles", carved.mesh.face_count()}, {"sweeps", sweeps},        {"seconds", carve_seconds},
        {"collision_free", left.empty()},   {"still_colliding", still},     {"mesh", mesh_file.string()},
        {"output", options.output}};
    fmt::print("{}\n", root.dump(2));
  } else {
    fmt::print("{} carved by {} over \"{}\": volume {:.6g} → {:.6g} ({} triangles) in {:.2f} s; wrote {} and {}\n",
               options.part, fmt::join(options.carvers, ", "), options.transition, carved.volume_before,
               carved.volume_after, carved.mesh.face_count(), carve_seconds, mesh_file.string(), options.output);
    for (const collision::CollisionInterval& ci : left)
      fmt::print("  still collides: {} at t ∈ [{:.4f}, {:.4f}]{}\n", parts_text(result, ci.parts), ci.t0, ci.t1,
                 options.t0 > 0 || options.t1 < 1 ? " (outside --from/--to?)" : " (grid or offset too coarse?)");
  }
  return left.empty() ? kExitOk : kExitCollisions;
}

void add_motion_options(CLI::App& command, SweepOptions& options) {
  command.add_option("scene", options.scene, "Scene file (reconfig-scene JSON)")->required();
  command.add_option("--transition", options.transition, "The transition whose motion sweeps")->required();
  command.add_option("--from", options.t0, "Start of the time range (a collision interval, say)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command.add_option("--to", options.t1, "End of the time range")->check(CLI::Range(0.0, 1.0))->capture_default_str();
  command.add_option("--grid", options.grid, "Grid step h (default: the swept box's longest side / 128)")
      ->check(CLI::NonNegativeNumber);
  command.add_option("--offset", options.offset, "Offset ε of the swept volume (clearance)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_flag("--json", options.json, "Print the result as JSON");
  add_allow_outside_paths_flag(command, options.load);
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep", "The volume a part sweeps over a transition, offset by ε, as a closed mesh (exit 0, 2 on bad input)");
  add_motion_options(*command, *options);
  command->add_option("--part", options->part, "The moving part")->required();
  command->add_option("--relative-to", options->relative_to, "Sweep in this part's rest frame (default: world)");
  command->add_option("--method", options->method,
                      "How: sdf (a conservative closed mesh from a swept signed distance) or screw (the screw-motion "
                      "envelope's quads and the end poses, for display)")
      ->check(CLI::IsMember({"sdf", "screw"}))
      ->capture_default_str();
  command->add_option("-o,--output", options->output, "Where to write the mesh (.obj or .stl)")->required();
  command->callback([options, &exit_code] { exit_code = run_sweep(*options); });
}

void add_carve_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SweepOptions>();
  CLI::App* command = app.add_subcommand(
      "carve",
      "Carve from a part the volume other parts sweep through it (exit 0: no longer collides with them, 1: still "
      "does or refused, 2: bad input)");
  add_motion_options(*command, *options);
  command->add_option("--part", options->part, "The part carved")->required();
  command->add_option("--by", options->carvers, "The carving parts (comma-separated)")->required()->delimiter(',');
  command->add_option("-o,--output", options->output, "Where to write the carved design (.json)")->required();
  command->add_flag("--stl", options->stl, "Also write the carved mesh as a binary STL beside its OBJ (for printing)");
  command->callback([options, &exit_code] { exit_code = run_carve(*options); });
}

}  // namespace reconfig::cli
