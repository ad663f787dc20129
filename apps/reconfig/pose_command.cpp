// reconfig pose SCENE — the whole scene posed at one instant (or in one state): an OBJ with one
// named object per part, or an STL of them all.

#include <fmt/format.h>

#include <vector>

#include "command.h"
#include "reconfig/common/input_error.h"
#include "reconfig/geometry/save_mesh.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {
namespace {

struct PoseOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  std::string transition;
  double time = 0;
  std::string state;
  std::string output;
};

/// The parts as one mesh (STL has no objects).
geometry::Mesh merged(const std::vector<geometry::ObjObject>& parts) {
  geometry::Mesh mesh;
  int vertices = 0, faces = 0;
  for (const geometry::ObjObject& part : parts) {
    vertices += part.mesh.vertex_count();
    faces += part.mesh.face_count();
  }
  mesh.V.resize(vertices, 3);
  mesh.F.resize(faces, 3);
  vertices = faces = 0;
  for (const geometry::ObjObject& part : parts) {
    mesh.V.middleRows(vertices, part.mesh.vertex_count()) = part.mesh.V;
    mesh.F.middleRows(faces, part.mesh.face_count()) = part.mesh.F.array() + vertices;
    vertices += part.mesh.vertex_count();
    faces += part.mesh.face_count();
  }
  return mesh;
}

int run_pose(const PoseOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  int transition = -1, state = -1;
  if (!options.transition.empty()) {
    transition = scene.find_transition(options.transition);
    if (transition < 0) throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", options.transition));
  } else {
    state = scene.find_state(options.state);
    if (state < 0) throw InputError(options.scene, "", fmt::format("no state named \"{}\"", options.state));
  }
  std::vector<geometry::ObjObject> posed;
  int faces = 0;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) {
    geometry::Mesh mesh = scene.parts[p].mesh;
    mesh.V = transition >= 0 ? scene.posed_vertices(transition, p, options.time) : scene.posed_vertices_in_state(state, p);
    faces += mesh.face_count();
    posed.push_back({scene.parts[p].name, std::move(mesh)});
  }
  const std::string extension = std::filesystem::path(options.output).extension().string();
  if (extension == ".stl") geometry::save_stl(options.output, merged(posed));
  else if (extension == ".obj") geometry::save_obj(options.output, posed);  // one named object per part
  else throw InputError(options.output, "", "output must end in .obj or .stl");
  fmt::print("wrote {} ({} parts, {} triangles)\n", options.output, scene.parts.size(), faces);
  return kExitOk;
}

}  // namespace

void add_pose_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<PoseOptions>();
  CLI::App* command = app.add_subcommand("pose", "Write the scene posed at a time of a transition (or in a state)");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  add_allow_outside_paths_flag(*command, options->load);
  auto* transition = command->add_option("--transition", options->transition, "Transition name");
  command->add_option("--time", options->time, "Time in [0, 1]")->check(CLI::Range(0.0, 1.0))->needs(transition);
  auto* state = command->add_option("--state", options->state, "State name (instead of a transition and time)");
  transition->excludes(state);
  command->add_option("-o,--output", options->output, "Output mesh: .obj (one named object per part) or .stl")->required();
  command->callback([options, &exit_code, transition, state] {
    if (transition->count() == 0 && state->count() == 0)
      throw InputError("", "", "give --transition NAME --time T, or --state NAME");
    exit_code = run_pose(*options);
  });
}

}  // namespace reconfig::cli
