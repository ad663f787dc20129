// reconfig linkage simulate|edit|plot|info — planar linkages: closed-form kinematics,
// function-preserving editing, motion-curve pictures (LinkEdit).

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "command.h"
#include "reconfig/common/input_error.h"
#include "reconfig/common/write_atomically.h"
#include "reconfig/linkage/curve_edit.h"
#include "reconfig/linkage/linkage_edit.h"
#include "reconfig/linkage/linkage_file.h"
#include "reconfig/linkage/linkage_svg.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::cli {
namespace {

using namespace reconfig::linkage;

constexpr double kPi = std::numbers::pi;
double to_radians(double degrees) { return degrees * kPi / 180; }
double to_degrees(double radians) { return radians * 180 / kPi; }

std::string joint_names(const Linkage& linkage, const std::vector<int>& joints) {
  std::string names;
  for (int k : joints) names += (names.empty() ? "\"" : ", \"") + linkage.joints[k].name + "\"";
  return names;
}

void note_complex_loops(const Linkage& linkage, const JointOrder& order) {
  if (order.stuck_joints.empty()) return;
  fmt::print(stderr, "note: joints {} form a complex loop the closed-form rules cannot solve; solved by Newton's method\n",
             joint_names(linkage, order.stuck_joints));
}

// The angle (radians) equal to `degrees` modulo a turn that the motion reaches from the
// initial configuration without crossing a dead point; throws if there is none.
double reachable_angle(const std::string& file, const MotionRange& range, double initial, double degrees) {
  const double angle = to_radians(degrees);
  const double turn = 2 * kPi;
  if (range.full_rotation) return angle + turn * std::round((initial - angle) / turn);
  if (range.contains(angle)) return range.lower + std::fmod(std::fmod(angle - range.lower, turn) + turn, turn);
  // Which dead point comes first on the way there: the nearer one, measured the way round.
  const double up = std::fmod(std::fmod(angle - range.upper, turn) + turn, turn);
  const double down = std::fmod(std::fmod(range.lower - angle, turn) + turn, turn);
  const bool upper = up <= down;
  throw InputError(file, "",
                   fmt::format("the motion hits a singularity at {:.3f}° before reaching {}°: {}; the crank {}",
                               to_degrees(upper ? range.upper : range.lower), degrees,
                               (upper ? range.upper_failure : range.lower_failure).message,
                               range.describe().substr(0, range.describe().find(" ("))));
}

struct SimulateOptions {
  std::string file;
  std::vector<double> angles;
  bool json = false;
};

int run_simulate(const SimulateOptions& options) {
  const Linkage linkage = read_linkage(options.file);
  const JointOrder order = order_joints(linkage);
  note_complex_loops(linkage, order);
  const SymbolicKinematics kinematics(linkage, order);
  const MotionRange range = motion_range(kinematics);
  const int n = static_cast<int>(linkage.joints.size());
  std::vector<Eigen::Matrix2Xd> frames;
  for (double degrees : options.angles) {
    const double angle = reachable_angle(options.file, range, kinematics.initial_angle(), degrees);
    kinematics.reset_continuation();
    Eigen::Matrix2Xd X;
    ReconstructionFailure failure;
    if (!kinematics.solve(angle, X, &failure))
      throw InputError(options.file, "", fmt::format("at {}°: {}", degrees, failure.message));
    frames.push_back(X);
  }
  if (options.json) {
    nlohmann::ordered_json doc;
    doc["angles"] = options.angles;
    nlohmann::ordered_json joints = nlohmann::ordered_json::object();
    for (int k = 0; k < n; ++k) {
      nlohmann::ordered_json positions = nlohmann::ordered_json::array();
      for (const auto& X : frames) positions.push_back({X(0, k), X(1, k)});
      joints[linkage.joints[k].name] = positions;
    }
    doc["joints"] = joints;
    fmt::print("{}\n", doc.dump());
    return kExitOk;
  }
  fmt::print("{} joints; motion: {}\n", n, range.describe());
  for (std::size_t a = 0; a < frames.size(); ++a) {
    fmt::print("angle {}°\n", options.angles[a]);
    for (int k = 0; k < n; ++k)
      fmt::print("  {:<12} {:>14.9f} {:>14.9f}\n", linkage.joints[k].name, frames[a](0, k), frames[a](1, k));
  }
  return kExitOk;
}

struct EditOptions {
  std::string file, output;
  std::vector<std::vector<std::string>> drags;
  std::vector<std::string> keep;
  std::vector<std::vector<std::string>> curve_drags, curve_transforms;
  std::vector<double> envelope;
  std::optional<double> at;  // degrees: drag joints of the configuration at this motor angle
  int samples = 72, iterations = 200;
};

int joint_or_tracking_point(const Linkage& linkage, const std::string& file, const std::string& name) {
  for (const auto& point : linkage.tracking_points)
    if (point.name == name) return point.joint;
  const int joint = linkage.find_joint(name);
  if (joint < 0) throw InputError(file, "", fmt::format("no joint or tracking point named \"{}\"", name));
  return joint;
}

double parse_number(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  throw InputError("", what, fmt::format("\"{}\" is not a number", text));
}

// The target curves of --curve-drag (soft selection) and --curve-transform (curve_edit.h), each
// made from the point's own motion curve at the edit's sample angles.
void add_target_curves(const Linkage& linkage, const EditOptions& options, const std::vector<double>& angles,
                       EditObjectives& objectives) {
  const bool closed = motion_range(SymbolicKinematics(linkage, order_joints(linkage))).full_rotation;
  for (const auto& drag : options.curve_drags) {
    const int joint = joint_or_tracking_point(linkage, options.file, drag[0]);
    const double index = parse_number(drag[1], "--curve-drag INDEX"), radius = parse_number(drag[4], "--curve-drag RADIUS");
    if (index != std::floor(index) || index < 0 || index >= static_cast<double>(angles.size()))
      throw InputError("", "--curve-drag", fmt::format("INDEX must be a sample index 0 … {}, not {}", angles.size() - 1, drag[1]));
    if (!(radius >= 0)) throw InputError("", "--curve-drag", "RADIUS must be ≥ 0");
    const Eigen::Vector2d displacement(parse_number(drag[2], "--curve-drag DX"), parse_number(drag[3], "--curve-drag DY"));
    objectives.trajectories.push_back(
        {joint, soft_drag_curve(joint_trajectory(linkage, joint, angles), static_cast<int>(index), displacement, radius, closed),
         10.0});
  }
  for (const auto& transform : options.curve_transforms) {
    const int joint = joint_or_tracking_point(linkage, options.file, transform[0]);
    const double scale = parse_number(transform[1], "--curve-transform SCALE");
    if (!(scale > 0)) throw InputError("", "--curve-transform", "SCALE must be > 0");
    const Eigen::Vector2d translation(parse_number(transform[3], "--curve-transform TX"),
                                      parse_number(transform[4], "--curve-transform TY"));
    objectives.trajectories.push_back({joint,
                                       transform_curve(joint_trajectory(linkage, joint, angles), scale,
                                                       to_radians(parse_number(transform[2], "--curve-transform DEGREES")),
                                                       translation),
                                       10.0});
  }
}

int run_edit(const EditOptions& options) {
  const Linkage linkage = read_linkage(options.file);
  note_complex_loops(linkage, order_joints(linkage));
  EditObjectives objectives;
  EditSettings settings;
  settings.samples = options.samples;
  settings.max_iterations = options.iterations;
  for (const auto& drag : options.drags) {
    if (drag.size() != 3) throw InputError("", "--drag", "expected JOINT X Y");
    const int joint = joint_or_tracking_point(linkage, options.file, drag[0]);
    std::optional<double> angle;
    if (options.at) {
      const SymbolicKinematics kinematics(linkage, order_joints(linkage));
      angle = reachable_angle(options.file, motion_range(kinematics), kinematics.initial_angle(), *options.at);
    }
    objectives.drags.push_back(
        {joint, {parse_number(drag[1], "--drag X"), parse_number(drag[2], "--drag Y")}, angle, 1.0});
  }
  const std::vector<double> angles = edit_sample_angles(linkage, settings.samples);
  for (const std::string& name : options.keep) {
    const int joint = joint_or_tracking_point(linkage, options.file, name);
    objectives.trajectories.push_back({joint, joint_trajectory(linkage, joint, angles), 10.0});
  }
  add_target_curves(linkage, options, angles, objectives);
  if (!options.envelope.empty()) {
    const auto& e = options.envelope;
    if (!(e[0] < e[2] && e[1] < e[3])) throw InputError("", "--envelope", "expected XMIN YMIN XMAX YMAX with min < max");
    objectives.envelope = EditObjectives::Envelope{{e[0], e[1]}, {e[2], e[3]}, 10.0};
  }
  if (objectives.drags.empty() && objectives.trajectories.empty() && !objectives.envelope)
    throw InputError("", "", "nothing to edit: give --drag, --keep-trajectory, --curve-drag, --curve-transform or --envelope");

  const EditResult result = edit_linkage(linkage, objectives, settings);
  write_linkage(result.linkage, options.output);
  fmt::print("energy {:.6g} -> {:.6g} ({} L-BFGS iterations, {}{})\n", result.energy_before, result.energy_after,
             result.iterations, result.status,
             result.shortened ? fmt::format(", step halved {}× to keep the motion working", result.shortened) : "");
  for (const auto& drag : objectives.drags) {
    auto position = [&](const Linkage& which) -> Eigen::Vector2d {
      if (!drag.angle) return which.joints[drag.joint].position;
      Eigen::Matrix2Xd X;
      SymbolicKinematics(which, order_joints(which)).solve(*drag.angle, X);
      return X.col(drag.joint);
    };
    fmt::print("drag {}{}: {:.6g} -> {:.6g} from the target\n", linkage.joints[drag.joint].name,
               drag.angle ? fmt::format(" at {}°", *options.at) : "", (position(linkage) - drag.target).norm(),
               (position(result.linkage) - drag.target).norm());
  }
  for (std::size_t t = 0; t < objectives.trajectories.size(); ++t) {
    const auto& trajectory = objectives.trajectories[t];
    const auto after = joint_trajectory(result.linkage, trajectory.joint, angles);
    double worst = 0;
    for (std::size_t s = 0; s < after.size(); ++s) worst = std::max(worst, (after[s] - trajectory.curve[s]).norm());
    fmt::print("{} of {}: largest deviation {:.6g}\n", t < options.keep.size() ? "trajectory" : "target curve",
               linkage.joints[trajectory.joint].name, worst);
  }
  const MotionRange range = motion_range(SymbolicKinematics(result.linkage, order_joints(result.linkage)));
  fmt::print("motion: {}\nwrote {}\n", range.describe(), options.output);
  return kExitOk;
}

struct PlotOptions {
  std::string file, output;
  int samples = 360;
};

int run_plot(const PlotOptions& options) {
  const Linkage linkage = read_linkage(options.file);
  SvgOptions svg;
  svg.samples = options.samples;
  svg.title = std::filesystem::path(options.file).filename().string();
  std::string text;
  try {
    text = linkage_svg(linkage, svg);
  } catch (const InputError& error) {
    throw error.in_file(options.file);
  }
  write_atomically(options.output, [&](std::ostream& out) { out << text; });
  fmt::print("wrote {}\n", options.output);
  return kExitOk;
}

int run_info(const std::string& file) {
  const Linkage linkage = read_linkage(file);
  const JointOrder order = order_joints(linkage);
  const SymbolicKinematics kinematics(linkage, order);
  fmt::print("{} joints, {} links; motor angle in the file: {:.3f}°\nreconstruction order:\n", linkage.joints.size(),
             linkage.links.size(), to_degrees(kinematics.initial_angle()));
  for (const Rule& rule : order.rules) fmt::print("  {}\n", describe_rule(linkage, order, rule));
  if (!order.stuck_joints.empty())
    fmt::print("complex loop (no closed-form rule; Newton fallback): {}\n", joint_names(linkage, order.stuck_joints));
  fmt::print("motion: {}\n", motion_range(kinematics).describe());
  return kExitOk;
}

}  // namespace

void add_linkage_command(CLI::App& app, int& exit_code) {
  CLI::App* linkage = app.add_subcommand("linkage", "Planar linkages: simulate, edit, plot");
  linkage->require_subcommand(1);

  auto simulate = std::make_shared<SimulateOptions>();
  CLI::App* sim = linkage->add_subcommand("simulate", "Joint positions at the given motor angles");
  sim->add_option("file", simulate->file, "Linkage file (reconfig-linkage JSON)")->required();
  sim->add_option("--angles", simulate->angles, "Motor angles in degrees, comma-separated")
      ->delimiter(',')
      ->required()
      ->allow_extra_args(false);
  sim->add_flag("--json", simulate->json, "Print {\"angles\", \"joints\": {name: [[x, y], ...]}}");
  sim->callback([simulate, &exit_code] { exit_code = run_simulate(*simulate); });

  auto edit = std::make_shared<EditOptions>();
  CLI::App* ed = linkage->add_subcommand("edit", "Edit the linkage while keeping it working (LinkEdit)");
  ed->add_option("file", edit->file, "Linkage file")->required();
  ed->add_option("--drag", edit->drags, "Move a joint of the initial configuration towards X Y")
      ->expected(3)
      ->type_name("JOINT X Y");
  ed->add_option("--at", edit->at, "Drag in the configuration at this motor angle (degrees), not the initial one");
  ed->add_option("--keep-trajectory", edit->keep, "Keep the motion curve of this tracking point (or joint)");
  ed->add_option("--curve-drag", edit->curve_drags,
                 "Target curve: this point's motion curve with sample INDEX moved by DX DY, its neighbours along the "
                 "curve less (soft selection of RADIUS)")
      ->expected(5)
      ->type_name("POINT INDEX DX DY RADIUS");
  ed->add_option("--curve-transform", edit->curve_transforms,
                 "Target curve: this point's motion curve scaled and turned (degrees) about its centroid, then moved")
      ->expected(5)
      ->type_name("POINT SCALE DEGREES TX TY");
  ed->add_option("--envelope", edit->envelope, "Keep every joint inside this box over the motion")
      ->expected(4)
      ->type_name("XMIN YMIN XMAX YMAX");
  ed->add_option("--samples", edit->samples, "Motor angles sampled over the motion")->check(CLI::Range(4, 3600));
  ed->add_option("--iterations", edit->iterations, "L-BFGS iterations")->check(CLI::Range(1, 100000));
  ed->add_option("-o,--output", edit->output, "Edited linkage file")->required();
  ed->callback([edit, &exit_code] { exit_code = run_edit(*edit); });

  auto plot = std::make_shared<PlotOptions>();
  CLI::App* pl = linkage->add_subcommand("plot", "Draw the linkage and its motion curves as SVG");
  pl->add_option("file", plot->file, "Linkage file")->required();
  pl->add_option("-o,--output", plot->output, "SVG file")->required();
  pl->add_option("--samples", plot->samples, "Points per motion curve")->check(CLI::Range(2, 100000));
  pl->callback([plot, &exit_code] { exit_code = run_plot(*plot); });

  auto info_file = std::make_shared<std::string>();
  CLI::App* in = linkage->add_subcommand("info", "Reconstruction order, complex loops and the motion range");
  in->add_option("file", *info_file, "Linkage file")->required();
  in->callback([info_file, &exit_code] { exit_code = run_info(*info_file); });
}

}  // namespace reconfig::cli
