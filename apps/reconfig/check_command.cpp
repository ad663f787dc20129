// reconfig check SCENE — spacetime collision detection over every transition (FORMATS.md).

#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "command.h"
#include "interrupt_guard.h"
#include "interval_view.h"
#include "visual_report.h"
#include "progress_bar.h"
#include "reconfig/collision/contact_tolerance.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/detector_settings.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/render/egl_context.h"
#include "reconfig/resolve/interval_energy.h"
#include "reconfig/resolve/proximity.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {
namespace {

struct CheckOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  bool json = false;
  bool reference = false;
  // The engine's settings given on the command line; each one given overrides the scene's.
  double tolerance = collision::DetectorOptions{}.tolerance;
  int dop = collision::halfspace_count(collision::DetectorOptions{}.dop);
  bool conservative = collision::DetectorOptions{}.conservative;
  double box_resolution = collision::DetectorOptions{}.box_resolution;
  double contact = 0;
  bool touching_collides = false;
  double clearance = 0;
  scene::CollisionSettings given;  ///< which of them were given
  bool all_contacts = false;
  bool energy = false;
  bool views = false;
  int threads = 0;
  int samples = 1000;
  std::vector<std::string> transitions;
  std::string report;
  std::string json_out;
};

/// What either detector found, and how it was found.
struct CheckOutcome {
  std::vector<collision::TransitionCollisions> transitions;
  std::string method;           ///< one line for people
  nlohmann::ordered_json facts;  ///< the same for scripts
  double seconds = 0;
  /// With --energy: per transition, per interval (same order as `transitions`).
  std::vector<std::vector<resolve::IntervalEnergy>> energies = {};
  /// With --views: per transition, per interval, its view at the severity time.
  std::vector<std::vector<render::BestView>> views = {};

  bool any_collision() const {
    for (const auto& t : transitions)
      if (!t.intervals.empty()) return true;
    return false;
  }
};

std::string part_names(const scene::Reconfigurable& scene, const collision::CollisionInterval& ci) {
  std::string names;
  for (int p : ci.parts) names += (names.empty() ? "" : " × ") + scene.parts[p].name;
  return names;
}

nlohmann::ordered_json to_json(const scene::Reconfigurable& scene, const CheckOutcome& outcome) {
  nlohmann::ordered_json root = outcome.facts;
  root["seconds"] = outcome.seconds;
  root["transitions"] = nlohmann::ordered_json::array();
  for (const auto& transition : outcome.transitions) {
    nlohmann::ordered_json intervals = nlohmann::ordered_json::array();
    const std::size_t t = &transition - outcome.transitions.data();
    for (const auto& ci : transition.intervals) {
      nlohmann::ordered_json parts = nlohmann::ordered_json::array();
      for (int p : ci.parts) parts.push_back(scene.parts[p].name);
      const Eigen::Vector3d lo = ci.box.min(), hi = ci.box.max();
      intervals.push_back({{"t0", ci.t0},
                           {"t1", ci.t1},
                           {"parts", parts},
                           {"box_min", {lo.x(), lo.y(), lo.z()}},
                           {"box_max", {hi.x(), hi.y(), hi.z()}},
                           {"kind", ci.clearance ? "clearance" : "collision"},
                           {"containment", ci.containment},
                           {"possible", ci.possible}});
      if (!outcome.energies.empty()) {
        const resolve::IntervalEnergy& e = outcome.energies[t][&ci - transition.intervals.data()];
        intervals.back()["energy"] = e.energy;
        intervals.back()["contour_energy"] = e.contour_energy;
        intervals.back()["penetration_energy"] = e.penetration_energy;
        intervals.back()["proximity_energy"] = e.proximity_energy;
        intervals.back()["severity_time"] = e.severity_time;
      }
      if (!outcome.views.empty())
        intervals.back()["view"] = view_json(outcome.views[t][&ci - transition.intervals.data()]);
    }
    root["transitions"].push_back({{"name", transition.name}, {"intervals", intervals}});
  }
  return root;
}

std::string box_text(const Eigen::AlignedBox3d& box) {
  const Eigen::Vector3d lo = box.min(), hi = box.max();
  return fmt::format("({:.3f}, {:.3f}, {:.3f}) – ({:.3f}, {:.3f}, {:.3f})", lo.x(), lo.y(), lo.z(), hi.x(), hi.y(),
                     hi.z());
}

std::string qualifiers(const collision::CollisionInterval& ci) {
  std::string text;
  if (ci.clearance) text += " (clearance: closer than allowed, not colliding)";
  if (ci.containment) text += " (one inside the other)";
  if (ci.possible) text += " (possible: within the tolerance)";
  return text;
}

std::string text_report(const scene::Reconfigurable& scene, const CheckOutcome& outcome, const std::string& file) {
  std::string out = fmt::format("{}: {} parts, {} states, {} transitions ({}; {:.3f} s)\n", file, scene.parts.size(),
                                scene.states.size(), scene.transitions.size(), outcome.method, outcome.seconds);
  for (const auto& transition : outcome.transitions) {
    const auto& tr = scene.transitions[transition.transition];
    out += fmt::format("transition \"{}\" ({} → {}): ", tr.name, tr.from, tr.to);
    if (transition.intervals.empty()) {
      out += "collision-free\n";
      continue;
    }
    const auto clearances = std::count_if(transition.intervals.begin(), transition.intervals.end(),
                                          [](const collision::CollisionInterval& ci) { return ci.clearance; });
    const auto collisions = static_cast<std::ptrdiff_t>(transition.intervals.size()) - clearances;
    if (collisions > 0) out += fmt::format("{} collision interval{}", collisions, collisions == 1 ? "" : "s");
    if (clearances > 0)
      out += fmt::format("{}{} clearance interval{}", collisions > 0 ? ", " : "", clearances, clearances == 1 ? "" : "s");
    out += "\n";
    for (const auto& ci : transition.intervals) {
      out += fmt::format("  t = {:.6f} – {:.6f}  {}{}  at {}\n", ci.t0, ci.t1, part_names(scene, ci), qualifiers(ci),
                         box_text(ci.box));
      if (!outcome.energies.empty()) {
        const auto& e = outcome.energies[&transition - outcome.transitions.data()][&ci - transition.intervals.data()];
        out += fmt::format(
            "      energy {:.4g} (contour {:.4g}, penetration {:.4g}, proximity {:.4g}), most severe at t = {:.3f}\n",
            e.energy, e.contour_energy, e.penetration_energy, e.proximity_energy, e.severity_time);
      }
      if (!outcome.views.empty()) {
        const auto& v = outcome.views[&transition - outcome.transitions.data()][&ci - transition.intervals.data()];
        const Eigen::Vector3d eye = v.camera.eye();
        out += fmt::format("      best seen from ({:.3f}, {:.3f}, {:.3f}), {:.0f} % of its box in sight\n", eye.x(),
                           eye.y(), eye.z(), 100 * v.pixels.visible_fraction());
      }
    }
  }
  return out;
}

std::string markdown_report(const scene::Reconfigurable& scene, const CheckOutcome& outcome, const std::string& file) {
  std::string out = fmt::format("# Collision report: `{}`\n\n", file);
  out += fmt::format("{} parts, {} states, {} transitions; {}.\n\n", scene.parts.size(), scene.states.size(),
                     scene.transitions.size(), outcome.method);
  for (const auto& transition : outcome.transitions) {
    const auto& tr = scene.transitions[transition.transition];
    out += fmt::format("## Transition `{}` ({} → {})\n\n", tr.name, tr.from, tr.to);
    if (transition.intervals.empty()) {
      out += "Collision-free.\n\n";
      continue;
    }
    out += "| from t | to t | parts | where (box) |\n|---|---|---|---|\n";
    for (const auto& ci : transition.intervals)
      out += fmt::format("| {:.6f} | {:.6f} | {}{} | {} |\n", ci.t0, ci.t1, part_names(scene, ci), qualifiers(ci),
                         box_text(ci.box));
    out += "\n";
  }
  return out;
}

void write_file(const std::string& path, const std::string& text) {
  write_atomically(path, [&](std::ostream& out) { out << text; });
}

/// ", clearance C" when a clearance is checked.
std::string clearance_text(double clearance) { return clearance > 0 ? fmt::format(", clearance {:g}", clearance) : ""; }

CheckOutcome run_reference(const scene::Reconfigurable& scene, const CheckOptions& options,
                           const std::vector<int>& transitions, const ProgressCallback& progress) {
  collision::ReferenceCheckRequest request;
  request.samples = options.samples;
  request.transitions = transitions;
  request.progress = progress;
  const scene::CollisionSettings settings = scene.collision.overridden_by(options.given);
  request.contact = settings.contact.value_or(0);
  request.touching_collides = settings.touching_collides.value_or(false);
  request.clearance = settings.clearance.value_or(0);
  const collision::ReferenceCheckResult result = collision::reference_check(scene, request);
  return {result.transitions,
          fmt::format("reference check, {} samples per transition (ends within {:.3g}), contact tolerance {:g}{}{}",
                      options.samples, result.time_error, result.contact,
                      request.touching_collides ? ", touching collides" : "", clearance_text(request.clearance)),
          {{"method", "reference"},
           {"samples", options.samples},
           {"time_error", result.time_error},
           {"contact", result.contact},
           {"touching_collides", request.touching_collides},
           {"clearance", request.clearance}},
          0};
}

CheckOutcome run_engine(const scene::Reconfigurable& scene, const CheckOptions& options,
                        const std::vector<int>& transitions, const ProgressCallback& progress) {
  collision::CollisionRequest request;
  request.detector = collision::with_settings({}, scene.collision.overridden_by(options.given));
  request.detector.all_contacts = options.all_contacts;
  request.transitions = transitions;
  request.progress = progress;
  collision::CollisionResult result;
  try {
    result = collision::detect_collisions(scene, request);
  } catch (const InputError& error) {  // a tolerance too fine for the design
    throw error.in_file(options.scene);
  }
  const collision::DetectorOptions& used = request.detector;
  const int dop = collision::halfspace_count(used.dop);
  const double contact = collision::contact_tolerance(scene, used.contact);
  return {result.transitions,
          fmt::format("spacetime engine, {}-DOP, tolerance {:g}, contact tolerance {:g}{}{}{}{}", dop, used.tolerance,
                      contact, used.touching_collides ? ", touching collides" : "", clearance_text(used.clearance),
                      used.conservative ? ", conservative" : "", options.all_contacts ? ", every contact" : ""),
          {{"method", "engine"},
           {"dop", dop},
           {"tolerance", used.tolerance},
           {"contact", contact},
           {"touching_collides", used.touching_collides},
           {"clearance", used.clearance},
           {"time_error", used.conservative ? 0.0 : collision::kIntervalEndTolerance},
           {"conservative", used.conservative},
           {"all_contacts", options.all_contacts},
           {"box_resolution", used.box_resolution},
           {"frame", used.frame},
           {"proxy_samples", result.stats.proxy_samples},
           {"narrow_phase_tests", result.stats.narrow_phase}},
          0};
}

/// The intersection energy and severity time of every interval (--energy), its proximity term
/// reaching as far as the engine's settings say (`resolve::proximity_reach`).
std::vector<std::vector<resolve::IntervalEnergy>> interval_energies(
    const scene::Reconfigurable& scene, const std::vector<collision::TransitionCollisions>& transitions,
    const CheckOptions& options) {
  const double reach =
      resolve::proximity_reach(collision::with_settings({}, scene.collision.overridden_by(options.given)));
  resolve::ShapeCache shapes;
  std::vector<std::vector<resolve::IntervalEnergy>> energies;
  for (const auto& transition : transitions) {
    energies.emplace_back();
    for (const auto& ci : transition.intervals)
      energies.back().push_back(resolve::interval_energy(scene, shapes, transition.transition, ci, 0.01, -1, reach));
  }
  return energies;
}

/// The view of every interval at its severity time (--views). Needs a current OpenGL context.
std::vector<std::vector<render::BestView>> interval_views(
    const scene::Reconfigurable& scene, const std::vector<collision::TransitionCollisions>& transitions,
    const std::vector<std::vector<resolve::IntervalEnergy>>& energies) {
  render::OcclusionCounter counter;
  std::vector<std::vector<render::BestView>> views;
  for (std::size_t t = 0; t < transitions.size(); ++t) {
    views.emplace_back();
    const collision::TransitionCollisions& transition = transitions[t];
    for (std::size_t i = 0; i < transition.intervals.size(); ++i)
      views.back().push_back(interval_best_view(counter, scene, transition.transition, transition.intervals[i],
                                                energies[t][i].severity_time));
  }
  return views;
}

int run_check(const CheckOptions& options) {
  std::optional<tbb::global_control> threads;
  if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  std::vector<int> transitions;
  for (const std::string& name : options.transitions) {
    const int index = scene.find_transition(name);
    if (index < 0) throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", name));
    transitions.push_back(index);
  }
  ProgressBar bar("checking", !options.json && stderr_is_terminal());
  const InterruptGuard interrupt;
  const auto start = std::chrono::steady_clock::now();
  const ProgressCallback progress = interrupt.wrap(bar.callback());
  CheckOutcome outcome = options.reference ? run_reference(scene, options, transitions, progress)
                                           : run_engine(scene, options, transitions, progress);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  bar.finish();
  if (interrupt.interrupted()) {
    fmt::print(stderr, "reconfig: check cancelled (Ctrl+C): no result\n");
    return kExitInterrupted;
  }
  // --report DIR/ (a folder: ends in "/" or exists as one) writes the visual report.
  const bool visual = !options.report.empty() &&
                      (options.report.back() == '/' || std::filesystem::is_directory(options.report));
  // The report needs energies and views too, without printing them unless asked.
  std::vector<std::vector<resolve::IntervalEnergy>> energies;
  std::vector<std::vector<render::BestView>> views;
  if (options.energy || options.views || visual) energies = interval_energies(scene, outcome.transitions, options);
  std::optional<render::EglContext> context;  // headless drawing: occlusion counts, pictures
  if (options.views || visual) {
    context.emplace();
    views = interval_views(scene, outcome.transitions, energies);
  }
  if (options.energy || options.views) outcome.energies = energies;
  if (options.views) outcome.views = views;
  const nlohmann::ordered_json json = to_json(scene, outcome);
  if (options.json) fmt::print("{}\n", json.dump(2));
  else fmt::print("{}", text_report(scene, outcome, options.scene));
  if (!options.json_out.empty()) write_file(options.json_out, json.dump(2) + "\n");
  if (visual)
    write_visual_report(options.report, scene,
                        {options.scene, outcome.method, outcome.transitions, energies, views},
                        markdown_report(scene, outcome, options.scene));
  else if (!options.report.empty())
    write_file(options.report, markdown_report(scene, outcome, options.scene));
  return outcome.any_collision() ? kExitCollisions : kExitOk;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command = app.add_subcommand(
      "check", "Spacetime collision detection over every transition (exit 0: none, 1: collisions, 2: bad input)");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  add_allow_outside_paths_flag(*command, options->load);
  command->add_flag("--json", options->json, "Print the result as JSON");
  command->add_flag("--reference", options->reference,
                    "Use the reference check (dense time sampling, exact static tests) instead of the engine");
  command->add_option("--tolerance", options->tolerance,
                      "Largest distance between proxy and true motion (engine; overrides the scene's)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--dop", options->dop, "Spacetime k-DOP family of the engine's BVH (overrides the scene's)")
      ->check(CLI::IsMember(scene::kDopHalfspaces))
      ->capture_default_str();
  command->add_flag("--conservative,!--no-conservative", options->conservative,
                    "Engine: also report near misses the true motion may turn into collisions (never misses one); "
                    "overrides the scene's");
  command->add_flag("--energy", options->energy,
                    "Also give each interval its intersection energy (contour length plus penetration depth plus "
                    "proximity deficit, integrated over time) and the time it is most severe");
  command->add_flag("--views", options->views,
                    "Also give each interval the camera that shows it best at its severity time (occlusion "
                    "queries over candidate views, drawn headless; implies --energy)");
  command->add_flag("--all-contacts", options->all_contacts,
                    "Engine: find every intersecting triangle pair instead of stopping once the intervals are known "
                    "(same intervals, slower on deep overlaps)");
  command->add_option("--box-resolution", options->box_resolution,
                      "Engine: round interval boxes outward to a grid of this fraction of the smaller part's size "
                      "(0: exact boxes, slower on deep overlaps; overrides the scene's)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--contact", options->contact,
                      "Contact tolerance δ: parts meeting by no more than this only touch (default 1e-6 of the "
                      "design's size; overrides the scene's)")
      ->check(CLI::PositiveNumber);
  command->add_flag("--touching-collides,!--no-touching-collides", options->touching_collides,
                    "Report parts that only touch (within the contact tolerance) as collisions too; overrides the "
                    "scene's");
  command->add_option("--clearance", options->clearance,
                      "Also report where two parts come closer than this distance without colliding, as clearance "
                      "intervals (exit code 1 like collisions; 0: none; overrides the scene's)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--threads", options->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  command->add_option("--samples", options->samples, "Time samples per transition (reference check)")
      ->check(CLI::Range(2, 10000000))
      ->capture_default_str();
  command->add_option("--transition", options->transitions, "Only check these transitions (repeatable)");
  command->add_option("--report", options->report,
                      "Also write a Markdown report to this file; to a folder (ending in /): a visual HTML report, "
                      "index.html with pictures of every interval from its best view, and report.md");
  command->add_option("--json-out", options->json_out, "Also write the JSON result to this file");
  command->callback([command, options, &exit_code] {
    if (command->count("--tolerance")) options->given.tolerance = options->tolerance;
    if (command->count("--dop")) options->given.dop = options->dop;
    if (command->count("--conservative") || command->count("--no-conservative"))
      options->given.conservative = options->conservative;
    if (command->count("--box-resolution")) options->given.box_resolution = options->box_resolution;
    if (command->count("--contact")) options->given.contact = options->contact;
    if (command->count("--touching-collides") || command->count("--no-touching-collides"))
      options->given.touching_collides = options->touching_collides;
    if (command->count("--clearance")) options->given.clearance = options->clearance;
    exit_code = run_check(*options);
  });
}

}  // namespace reconfig::cli
