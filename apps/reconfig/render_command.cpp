// reconfig render SCENE — a picture of the scene at one instant (or in one state), drawn
// headless with the same renderer as the studio (OpenGL through EGL surfaceless, Mesa).

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "command.h"
#include "interval_view.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/detector_settings.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/common/input_error.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/render/renderer.h"
#include "reconfig/render/scene_draw_list.h"
#include "reconfig/resolve/interval_energy.h"
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
  int interval = -1;
  bool best_view = false;
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

/// Interval K of the transition (the engine's, as `check` lists them): draws it at its severity
/// time, its box shown and its parts selected.
collision::CollisionInterval focus_interval(const scene::Reconfigurable& scene, const RenderOptions& options,
                                            render::SceneDrawRequest& request) {
  collision::CollisionRequest detect;
  detect.detector = collision::with_settings({}, scene.collision);
  detect.transitions = {request.transition};
  const collision::CollisionResult found = collision::detect_collisions(scene, detect);
  const std::vector<collision::CollisionInterval>& intervals = found.transitions.front().intervals;
  if (options.interval >= static_cast<int>(intervals.size()))
    throw InputError(options.scene, "--interval",
                     fmt::format("transition \"{}\" has {} collision interval{} (K counts from 0)", options.transition,
                                 intervals.size(), intervals.size() == 1 ? "" : "s"));
  const collision::CollisionInterval& ci = intervals[options.interval];
  resolve::ShapeCache shapes;
  request.time = resolve::interval_energy(scene, shapes, request.transition, ci).severity_time;
  request.boxes.push_back(ci.box);
  if (request.selected.empty()) request.selected = ci.parts;
  return ci;
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
  if ((options.ghosts > 0 || options.intervals || options.interval >= 0) && request.transition < 0)
    throw InputError("", "", "--ghosts, --intervals and --interval need --transition NAME");
  if (options.best_view && options.interval < 0) throw InputError("", "--best-view", "needs --interval K");
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

  std::optional<collision::CollisionInterval> focus;
  if (options.interval >= 0) focus = focus_interval(scene, options, request);
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

  render::EglContext context;
  view::Camera camera = render_camera(scene, options.camera, bounds, static_cast<double>(width) / height);
  if (options.best_view) {
    render::OcclusionCounter counter;
    camera = picture_camera(interval_best_view(counter, scene, request.transition, *focus, request.time), bounds);
  }
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
  if (focus) what += fmt::format(", interval {} at its severity time{}", options.interval, options.best_view ? ", best view" : "");
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
  auto* time = command->add_option("--time", options->time, "Time in [0, 1]")->check(CLI::Range(0.0, 1.0))->needs(transition);
  auto* state = command->add_option("--state", options->state, "State name (default: the first state)");
  transition->excludes(state);
  command->add_option("--ghosts", options->ghosts, "Ghosts before and after the time (transparent copies)")
      ->check(CLI::Range(0, 50));
  command->add_option("--ghost-spacing", options->ghost_spacing, "Time between ghosts")
      ->check(CLI::Range(1e-3, 1.0));
  command->add_flag("--intervals", options->intervals, "Draw the collision interval boxes that overlap the time");
  auto* interval = command->add_option("--interval", options->interval,
                                       "Show collision interval K (from 0, as `check` lists them) of the transition at "
                                       "its severity time, its box drawn and its parts selected")
                       ->check(CLI::NonNegativeNumber)
                       ->needs(transition)
                       ->excludes(time);
  auto* best = command->add_flag("--best-view", options->best_view,
                                 "With --interval: look from the view that shows the interval best (occlusion counts)")
                   ->needs(interval);
  command->add_option("--samples", options->samples, "Time samples of the collision check behind --intervals")
      ->check(CLI::Range(2, 100000));
  command->add_option("--camera", options->camera, "yaw,pitch[,distance] (degrees, framing all parts; default: the scene's saved view, else its working side)")
      ->excludes(best);
  command->add_option("--size", options->size, "Image size WIDTHxHEIGHT (default 1280x720)");
  command->add_option("--select", options->selected, "Part to highlight (repeatable)");
  command->add_flag("--no-grid", options->no_grid, "Leave out the ground grid");
  command->add_option("--msaa", options->msaa, "Multisampling samples (0: off)")->check(CLI::Range(0, 16));
  command->add_option("-o,--output", options->output, "Output image (.png)")->required();
  command->callback([options, &exit_code] { exit_code = run_render(*options); });
}

}  // namespace reconfig::cli
