// reconfig render SCENE — a picture of the scene at one instant (or in one state), drawn
// headless with the same renderer as the studio (OpenGL through EGL surfaceless, Mesa).

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "command.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/common/input_error.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/render/renderer.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/view/ghost_sampling.h"
#include "reconfig/view/saved_camera.h"
#include "reconfig/view/scene_bounds.h"
#include "reconfig/view/working_side.h"

namespace reconfig::cli {
namespace {

constexpr double kDegree = M_PI / 180;

struct RenderOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  std::string transition;
  double time = 0;
  std::string state;
  int ghosts = 0;
  double ghost_spacing = 0.1;
  bool intervals = false;
  int samples = 200;
  std::string camera;
  std::string size = "1280x720";
  std::vector<std::string> selected;
  bool no_grid = false;
  int msaa = 4;
  std::string output;
};

std::vector<double> parse_numbers(const std::string& text, const std::string& option) {
  std::vector<double> numbers;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    try {
      std::size_t used = 0;
      numbers.push_back(std::stod(item, &used));
      if (used != item.size() || !std::isfinite(numbers.back())) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("", option, fmt::format("\"{}\" is not a number", item));
    }
  }
  return numbers;
}

/// The --camera angles framing `bounds`, else the scene's saved view, else a framed view of
/// its working side (as the studio opens it).
view::Camera render_camera(const scene::Reconfigurable& scene, const std::string& option,
                           const Eigen::AlignedBox3d& bounds, double aspect) {
  if (option.empty() && scene.view) return view::camera_from(*scene.view, bounds);
  view::Camera camera;
  view::aim_at_working_side(camera, scene);
  double distance = 0;
  if (!option.empty()) {
    const std::vector<double> numbers = parse_numbers(option, "--camera");
    if (numbers.size() < 2 || numbers.size() > 3 || std::abs(numbers[1]) > 89 || (numbers.size() == 3 && numbers[2] <= 0))
      throw InputError("", "--camera", "expected yaw,pitch[,distance]: degrees, |pitch| ≤ 89, distance > 0");
    camera.yaw = numbers[0] * kDegree;
    camera.pitch = numbers[1] * kDegree;
    if (numbers.size() == 3) distance = numbers[2];
  }
  camera.frame_all(bounds, aspect);
  if (distance > 0) camera.zoom(distance / camera.distance);
  return camera;
}

int run_render(const RenderOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  render::SceneDrawRequest request;
  if (!options.transition.empty()) {
    request.transition = scene.find_transition(options.transition);
    if (request.transition < 0)
      throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", options.transition));
    request.time = options.time;
  } else if (!options.state.empty()) {
    request.state = scene.find_state(options.state);
    if (request.state < 0) throw InputError(options.scene, "", fmt::format("no state named \"{}\"", options.state));
  } else {
    if (scene.states.empty()) throw InputError(options.scene, "", "the scene has no state to show");
    request.state = 0;
  }
  if ((options.ghosts > 0 || options.intervals) && request.transition < 0)
    throw InputError("", "", "--ghosts and --intervals need --transition NAME --time T");
  for (const std::string& name : options.selected) {
    const int part = scene.find_part(name);
    if (part < 0) throw InputError(options.scene, "", fmt::format("no part named \"{}\"", name));
    request.selected.push_back(part);
  }

  int width = 0, height = 0;
  {
    char x = 0;
    std::stringstream stream(options.size);
    if (!(stream >> width >> x >> height) || x != 'x' || !stream.eof() || width < 16 || height < 16 || width > 8192 ||
        height > 8192)
      throw InputError("", "--size", fmt::format("\"{}\" is not WIDTHxHEIGHT with sides in 16–8192", options.size));
  }
  if (std::filesystem::path(options.output).extension() != ".png")
    throw InputError(options.output, "", "output must end in .png");

  Eigen::AlignedBox3d bounds = request.transition >= 0 ? view::scene_bounds_at(scene, request.transition, request.time)
                                                       : view::scene_bounds_in_state(scene, request.state);
  if (options.ghosts > 0) {
    request.ghosts = view::ghost_samples({.current = request.time, .count = options.ghosts, .spacing = options.ghost_spacing});
    for (const view::GhostSample& ghost : request.ghosts)
      bounds.extend(view::scene_bounds_at(scene, request.transition, ghost.time));
  }
  int shown_intervals = 0;
  if (options.intervals) {
    collision::ReferenceCheckRequest check;
    check.samples = options.samples;
    check.transitions = {request.transition};
    const collision::ReferenceCheckResult result = collision::reference_check(scene, check);
    const double slack = 0.5 / (options.samples - 1);  // an instant between two samples still counts
    for (const collision::CollisionInterval& ci : result.transitions.front().intervals)
      if (ci.t0 - slack <= request.time && request.time <= ci.t1 + slack) {
        request.boxes.push_back(ci.box);
        ++shown_intervals;
      }
  }
  request.grid = !options.no_grid;

  const view::Camera camera = render_camera(scene, options.camera, bounds, static_cast<double>(width) / height);

  render::EglContext context;
  render::Renderer renderer({.samples = options.msaa});
  const render::DrawList list = render::scene_draw_list(scene, request);
  const auto start = std::chrono::steady_clock::now();
  const render::Image image = renderer.render(list, camera, width, height);
  const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  render::write_png(options.output, image);
  std::string what = request.transition >= 0
                         ? fmt::format("\"{}\" at t = {}", scene.transitions[request.transition].name, request.time)
                         : fmt::format("state \"{}\"", scene.states[request.state].name);
  if (!request.ghosts.empty()) what += fmt::format(", {} ghost times", request.ghosts.size());
  if (options.intervals) what += fmt::format(", {} collision interval box{}", shown_intervals, shown_intervals == 1 ? "" : "es");
  fmt::print("wrote {} ({}×{}, {}; frame {:.0f} ms on {})\n", options.output, width, height, what, milliseconds,
             context.renderer());
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand("render", "Draw the scene at a time of a transition (or in a state) to a PNG, headless");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  add_allow_outside_paths_flag(*command, options->load);
  auto* transition = command->add_option("--transition", options->transition, "Transition name");
  command->add_option("--time", options->time, "Time in [0, 1]")->check(CLI::Range(0.0, 1.0))->needs(transition);
  auto* state = command->add_option("--state", options->state, "State name (default: the first state)");
  transition->excludes(state);
  command->add_option("--ghosts", options->ghosts, "Ghosts before and after the time (transparent copies)")
      ->check(CLI::Range(0, 50));
  command->add_option("--ghost-spacing", options->ghost_spacing, "Time between ghosts")
      ->check(CLI::Range(1e-3, 1.0));
  command->add_flag("--intervals", options->intervals, "Draw the collision interval boxes that overlap the time");
  command->add_option("--samples", options->samples, "Time samples of the collision check behind --intervals")
      ->check(CLI::Range(2, 100000));
  command->add_option("--camera", options->camera, "yaw,pitch[,distance] (degrees, framing all parts; default: the scene's saved view, else its working side)");
  command->add_option("--size", options->size, "Image size WIDTHxHEIGHT (default 1280x720)");
  command->add_option("--select", options->selected, "Part to highlight (repeatable)");
  command->add_flag("--no-grid", options->no_grid, "Leave out the ground grid");
  command->add_option("--msaa", options->msaa, "Multisampling samples (0: off)")->check(CLI::Range(0, 16));
  command->add_option("-o,--output", options->output, "Output image (.png)")->required();
  command->callback([options, &exit_code] { exit_code = run_render(*options); });
}

}  // namespace reconfig::cli
