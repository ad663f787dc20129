// reconfig check SCENE — spacetime collision detection over every transition (FORMATS.md).

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "command.h"
#include "progress_bar.h"
#include "reconfig/collision/reference_check.h"
#include "reconfig/common/input_error.h"
#include "reconfig/scene/scene_file.h"

namespace reconfig::cli {
namespace {

struct CheckOptions {
  std::string scene;
  bool json = false;
  int samples = 1000;
  std::vector<std::string> transitions;
  std::string report;
  std::string json_out;
};

std::string part_names(const scene::Reconfigurable& scene, const collision::CollisionInterval& ci) {
  std::string names;
  for (int p : ci.parts) names += (names.empty() ? "" : " × ") + scene.parts[p].name;
  return names;
}

nlohmann::ordered_json to_json(const scene::Reconfigurable& scene, const collision::ReferenceCheckResult& result) {
  nlohmann::ordered_json root;
  root["samples"] = result.samples;
  root["transitions"] = nlohmann::ordered_json::array();
  for (const auto& transition : result.transitions) {
    nlohmann::ordered_json intervals = nlohmann::ordered_json::array();
    for (const auto& ci : transition.intervals) {
      nlohmann::ordered_json parts = nlohmann::ordered_json::array();
      for (int p : ci.parts) parts.push_back(scene.parts[p].name);
      const Eigen::Vector3d lo = ci.box.min(), hi = ci.box.max();
      intervals.push_back({{"t0", ci.t0},
                           {"t1", ci.t1},
                           {"parts", parts},
                           {"box_min", {lo.x(), lo.y(), lo.z()}},
                           {"box_max", {hi.x(), hi.y(), hi.z()}},
                           {"containment", ci.containment}});
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

std::string text_report(const scene::Reconfigurable& scene, const collision::ReferenceCheckResult& result,
                        const std::string& file) {
  std::string out = fmt::format("{}: {} parts, {} states, {} transitions ({} samples per transition)\n", file,
                                scene.parts.size(), scene.states.size(), scene.transitions.size(), result.samples);
  for (const auto& transition : result.transitions) {
    const auto& tr = scene.transitions[transition.transition];
    out += fmt::format("transition \"{}\" ({} → {}): ", tr.name, tr.from, tr.to);
    if (transition.intervals.empty()) {
      out += "collision-free\n";
      continue;
    }
    out += fmt::format("{} collision interval{}\n", transition.intervals.size(),
                       transition.intervals.size() == 1 ? "" : "s");
    for (const auto& ci : transition.intervals)
      out += fmt::format("  t = {:.3f} – {:.3f}  {}{}  at {}\n", ci.t0, ci.t1, part_names(scene, ci),
                         ci.containment ? " (one inside the other)" : "", box_text(ci.box));
  }
  return out;
}

std::string markdown_report(const scene::Reconfigurable& scene, const collision::ReferenceCheckResult& result,
                            const std::string& file) {
  std::string out = fmt::format("# Collision report: `{}`\n\n", file);
  out += fmt::format("{} parts, {} states, {} transitions; {} time samples per transition.\n\n", scene.parts.size(),
                     scene.states.size(), scene.transitions.size(), result.samples);
  for (const auto& transition : result.transitions) {
    const auto& tr = scene.transitions[transition.transition];
    out += fmt::format("## Transition `{}` ({} → {})\n\n", tr.name, tr.from, tr.to);
    if (transition.intervals.empty()) {
      out += "Collision-free.\n\n";
      continue;
    }
    out += "| from t | to t | parts | where (box) |\n|---|---|---|---|\n";
    for (const auto& ci : transition.intervals)
      out += fmt::format("| {:.3f} | {:.3f} | {}{} | {} |\n", ci.t0, ci.t1, part_names(scene, ci),
                         ci.containment ? " (nested)" : "", box_text(ci.box));
    out += "\n";
  }
  return out;
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  if (!out) throw InputError(path, "", "could not write the file");
}

int run_check(const CheckOptions& options) {
  const scene::Reconfigurable scene = scene::load_scene(options.scene);
  collision::ReferenceCheckRequest request;
  request.samples = options.samples;
  for (const std::string& name : options.transitions) {
    const int index = scene.find_transition(name);
    if (index < 0) throw InputError(options.scene, "", fmt::format("no transition named \"{}\"", name));
    request.transitions.push_back(index);
  }
  ProgressBar bar("checking", !options.json && stderr_is_terminal());
  request.progress = bar.callback();
  const collision::ReferenceCheckResult result = collision::reference_check(scene, request);
  bar.finish();
  const nlohmann::ordered_json json = to_json(scene, result);
  if (options.json) fmt::print("{}\n", json.dump(2));
  else fmt::print("{}", text_report(scene, result, options.scene));
  if (!options.json_out.empty()) write_file(options.json_out, json.dump(2) + "\n");
  if (!options.report.empty()) write_file(options.report, markdown_report(scene, result, options.scene));
  return result.any_collision() ? kExitCollisions : kExitOk;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* command = app.add_subcommand(
      "check", "Spacetime collision detection over every transition (exit 0: none, 1: collisions, 2: bad input)");
  command->add_option("scene", options->scene, "Scene file (reconfig-scene JSON)")->required();
  command->add_flag("--json", options->json, "Print the result as JSON");
  command->add_option("--samples", options->samples, "Time samples per transition")
      ->check(CLI::Range(2, 10000000))
      ->capture_default_str();
  command->add_option("--transition", options->transitions, "Only check these transitions (repeatable)");
  command->add_option("--report", options->report, "Also write a Markdown report to this file");
  command->add_option("--json-out", options->json_out, "Also write the JSON result to this file");
  command->callback([options, &exit_code] { exit_code = run_check(*options); });
}

}  // namespace reconfig::cli
