// reconfig resolve SCENE --transition T (--hint PART | --auto -o OUT) — resolution hints and
// automatic resolution of a transition's collisions (docs/file-formats.md, "reconfig resolve").

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include "command.h"
#include "progress_bar.h"
#include "reconfig/collision/detect_collisions.h"
#include "reconfig/collision/detector_settings.h"
#include "reconfig/common/input_error.h"
#include "reconfig/resolve/auto_resolve.h"
#include "reconfig/resolve/hints.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {
namespace {

struct ResolveOptions {
  std::string scene;
  scene::SceneLoadOptions load;
  std::string transition;
  std::string hint_part;
  bool automatic = false;
  std::string output;
  bool json = false;
  bool move_times = false;
  bool move_states = false;
  int max_rounds = resolve::AutoResolveRequest{}.max_rounds;
};

nlohmann::ordered_json vector_json(const Eigen::VectorXd& v) {
  if (v.size() == 1) return v[0];
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (double x : v) array.push_back(x);
  return array;
}

std::string vector_text(const Eigen::VectorXd& v) {
  if (v.size() == 1) return fmt::format("{:+.4f}", v[0]);
  return fmt::format("({:+.4f}, {:+.4f}, {:+.4f})", v[0], v[1], v[2]);
}

std::string track_name(scene::KeyKind kind) { return kind == scene::KeyKind::kTranslation ? "translation" : "rotation"; }

int run_hint(const scene::Reconfigurable& scene, int transition, const ResolveOptions& options) {
  const int part = scene.find_part(options.hint_part);
  if (part < 0) throw InputError(options.scene, "", fmt::format("no part named \"{}\"", options.hint_part));
  collision::CollisionRequest detection;
  detection.detector = collision::with_settings({}, scene.collision);
  detection.transitions = {transition};
  const auto intervals = collision::detect_collisions(scene, detection).transitions.at(0).intervals;
  resolve::ShapeCache shapes;
  const resolve::HintResult result =
      resolve::compute_hints(scene, shapes, {.transition = transition, .part = part, .intervals = intervals});
  if (options.json) {
    nlohmann::ordered_json hints = nlohmann::ordered_json::array();
    for (const resolve::Hint& hint : result.hints) {
      nlohmann::ordered_json entry = {{"kind", resolve::dof_kind_name(hint.dof.kind)}, {"key", hint.dof.key}};
      if (hint.dof.kind == resolve::DofKind::kTime) entry["track"] = track_name(hint.dof.track);
      entry["direction"] = vector_json(hint.direction);
      entry["slope"] = hint.slope;
      entry["gradient"] = vector_json(hint.gradient);
      hints.push_back(entry);
    }
    const nlohmann::ordered_json root = {{"transition", options.transition},   {"part", options.hint_part},
                                         {"energy", result.energy},            {"severity_time", result.severity_time},
                                         {"hints", hints}};
    fmt::print("{}\n", root.dump(2));
    return kExitOk;
  }
  fmt::print("{} in \"{}\": energy {:.4g}, most severe at t = {:.3f}\n", options.hint_part, options.transition,
             result.energy, result.severity_time);
  if (result.energy == 0) fmt::print("  no collision of this part to resolve\n");
  else if (result.hints.empty()) fmt::print("  the part has no keyframed degrees of freedom in this transition\n");
  for (const resolve::Hint& hint : result.hints) {
    const std::string what = hint.dof.kind == resolve::DofKind::kTime
                                 ? fmt::format("time of {} key {}", track_name(hint.dof.track), hint.dof.key)
                                 : fmt::format("{} of key {}", resolve::dof_kind_name(hint.dof.kind), hint.dof.key);
    fmt::print("  {:<28} move along {}  (energy falls {:.4g} per unit)\n", what, vector_text(hint.direction), -hint.slope);
  }
  return kExitOk;
}

int run_auto(const scene::Reconfigurable& scene, int transition, const ResolveOptions& options) {
  if (options.output.empty()) throw InputError("", "", "--auto needs -o OUT.json, where the resolved design is written");
  ProgressBar bar("resolving", !options.json && stderr_is_terminal());
  resolve::AutoResolveRequest request;
  request.transition = transition;
  request.detector = collision::with_settings({}, scene.collision);
  request.max_rounds = options.max_rounds;
  request.move_times = options.move_times;
  request.move_states = options.move_states;
  request.progress = bar.callback();
  request.on_round = [&](const resolve::ResolveRound& round) {
    if (options.json) return;
    bar.finish();
    fmt::print("round {}: {} × {}: energy {:.4g} → {:.4g} in {} step{}{}\n", round.round + 1,
               scene.parts[round.pair[0]].name, scene.parts[round.pair[1]].name, round.energy_before,
               round.energy_after, round.steps, round.steps == 1 ? "" : "s",
               round.inserted_keys.empty() ? "" : fmt::format(" (inserted {} key(s))", round.inserted_keys.size()));
    if (!round.moved_states.empty()) fmt::print("  moved {}\n", fmt::join(round.moved_states, ", "));
    if (!round.undone_because.empty()) fmt::print("  undone: {}\n", round.undone_because);
  };
  resolve::AutoResolveResult result = resolve::auto_resolve(scene, request);
  bar.finish();
  scene::save_scene(result.scene, options.output);
  if (options.json) {
    nlohmann::ordered_json rounds = nlohmann::ordered_json::array();
    for (const resolve::ResolveRound& round : result.rounds)
      rounds.push_back({{"round", round.round + 1},
                        {"parts", {scene.parts[round.pair[0]].name, scene.parts[round.pair[1]].name}},
                        {"energy_before", round.energy_before},
                        {"energy_after", round.energy_after},
                        {"steps", round.steps},
                        {"inserted_keys", round.inserted_keys},
                        {"moved_states", round.moved_states},
                        {"undone_because", round.undone_because}});
    nlohmann::ordered_json rechecked = nlohmann::ordered_json::array();
    for (const auto& [name, intervals] : result.rechecked)
      rechecked.push_back({{"transition", name}, {"intervals", intervals}});
    const nlohmann::ordered_json root = {{"transition", options.transition}, {"collision_free", result.collision_free},
                                         {"intervals_left", result.intervals_left},
                                         {"stopped_because", result.stopped_because}, {"rounds", rounds},
                                         {"rechecked", rechecked}, {"output", options.output}};
    fmt::print("{}\n", root.dump(2));
  } else {
    fmt::print("{}: {}; wrote {}\n", options.transition, result.stopped_because, options.output);
    for (const auto& [name, intervals] : result.rechecked)
      fmt::print("  {} (through a moved state): {}\n", name,
                 intervals == 0 ? "collision-free" : fmt::format("{} collision interval(s)", intervals));
  }
  return result.collision_free ? kExitOk : kExitCollisions;
}

int run_resolve(const ResolveOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene, options.load);
  const int transition = scene.find_transition(options.transition);
  if (transition < 0) throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", options.transition));
  return options.automatic ? run_auto(scene, transition, options) : run_hint(scene, transition, options);
}

}  // namespace

void add_resolve_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ResolveOptions>();
  CLI::App* command = app.add_subcommand(
      "resolve",
      "Hints for removing a part's collisions, or automatic resolution of a transition (--auto: exit 0 when it is "
      "now collision-free, 1 when collisions remain, 2 on bad input)");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  command->add_option("--transition", options->transition, "The transition to resolve")->required();
  auto* hint = command->add_option("--hint", options->hint_part,
                                   "Print how each of this part's keys should move to lower the collision energy");
  auto* automatic = command->add_flag("--auto", options->automatic,
                                      "Move the transition's inner keys until it is collision-free (or no step helps)");
  hint->excludes(automatic);
  command->add_option("-o,--output", options->output, "--auto: where to write the resolved design")->needs(automatic);
  command->add_flag("--move-times", options->move_times, "--auto: the keys' times may move too")->needs(automatic);
  command
      ->add_flag("--move-states", options->move_states,
                 "--auto: the end keys may move too, and with them the states (every transition through a moved "
                 "state is re-checked; a round that gives one more collisions is undone)")
      ->needs(automatic);
  command->add_option("--max-rounds", options->max_rounds, "--auto: greedy rounds at most (one pair each)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str()
      ->needs(automatic);
  command->add_flag("--json", options->json, "Print the result as JSON");
  add_allow_outside_paths_flag(*command, options->load);
  command->callback([command, options, &exit_code] {
    if (!command->count("--hint") && !options->automatic)
      throw InputError("", "", "resolve needs --hint PART or --auto -o OUT.json");
    exit_code = run_resolve(*options);
  });
}

}  // namespace reconfig::cli
