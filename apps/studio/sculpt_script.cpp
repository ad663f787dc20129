#include "sculpt_script.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "script.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// `args[i]` as a number, or a message in `problem`.
double number(const std::vector<std::string>& args, std::size_t i, const char* what, std::string& problem) {
  const std::optional<double> value = i < args.size() ? script_number(args[i]) : std::nullopt;
  if (!value && problem.empty()) problem = fmt::format("{}: a number", what);
  return value.value_or(0);
}

std::string set_mode(Studio& studio, const std::vector<std::string>& args) {
  if (args.size() != 1 || (args[0] != "on" && args[0] != "off")) return "sculpt-mode on|off";
  const bool on = args[0] == "on";
  if (studio.sculpt().set_mode(studio, on) != on) return studio.status();
  return {};
}

std::string set_tool(Studio& studio, const std::vector<std::string>& args) {
  SculptPanel::Settings& settings = studio.sculpt().settings();
  std::string problem;
  if (args.size() == 3 && args[0] == "part") {
    settings.tool_part = studio.document()->scene().find_part(args[1]);
    if (settings.tool_part < 0) return fmt::format("no part \"{}\"", args[1]);
    settings.shape = 4;
    settings.coating = number(args, 2, "coating", problem);
    return problem;
  }
  const std::vector<std::string> shapes = {"sphere", "box", "capsule", "ellipsoid"};
  const auto shape = args.empty() ? shapes.end() : std::find(shapes.begin(), shapes.end(), args[0]);
  if (args.size() != 5 || shape == shapes.end()) return "sculpt-tool sphere|box|capsule|ellipsoid SX SY SZ COATING, or part NAME COATING";
  settings.shape = static_cast<int>(shape - shapes.begin());
  settings.size = {number(args, 1, "size x", problem), number(args, 2, "size y", problem), number(args, 3, "size z", problem)};
  settings.coating = number(args, 4, "coating", problem);
  return problem;
}

/// sculpt-center X Y Z: the tool's center in the part's rest frame (the inspector's field).
std::string set_center(Studio& studio, const std::vector<std::string>& args) {
  std::string problem;
  const Eigen::Vector3d center(number(args, 0, "x", problem), number(args, 1, "y", problem), number(args, 2, "z", problem));
  if (problem.empty()) studio.sculpt().settings().center = center;
  return problem;
}

/// sculpt-view +x|-x|+y|-y|+z: the eye on that side, looking at the target level (straight down
/// for +z), so drags along the other two axes stay in the view plane.
std::string set_view(Studio& studio, const std::vector<std::string>& args) {
  static const std::pair<const char*, std::pair<double, double>> kViews[] = {
      {"+x", {0, 0}}, {"-x", {M_PI, 0}}, {"+y", {M_PI / 2, 0}}, {"-y", {-M_PI / 2, 0}}, {"+z", {-M_PI / 2, view::Camera::kMaxPitch}}};
  for (const auto& [name, angles] : kViews)
    if (args.size() == 1 && args[0] == name) {
      studio.camera().yaw = angles.first;
      studio.camera().pitch = angles.second;
      return {};
    }
  return "sculpt-view +x|-x|+y|-y|+z";
}

/// The tool's center on screen, or a message.
std::optional<ImVec2> tool_on_screen(Studio& studio, std::string& problem) {
  if (!studio.sculpt().mode()) problem = "sculpt mode is off (sculpt-mode on)";
  const std::optional<Eigen::Vector3d> center = problem.empty() ? studio.sculpt().tool_center(studio) : std::nullopt;
  const std::optional<ImVec2> at = center ? studio.viewport_point(*center) : std::nullopt;
  if (!at && problem.empty()) problem = "the tool is not in view";
  return at;
}

std::string place(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  std::string problem;
  const Eigen::Vector3d target(number(args, 0, "x", problem), number(args, 1, "y", problem), number(args, 2, "z", problem));
  const std::optional<ImVec2> from = tool_on_screen(frontend.studio(), problem);
  const std::optional<ImVec2> to = frontend.studio().viewport_point(target);
  if (!problem.empty()) return problem;
  if (!to) return "that point is not in view";
  drag_through(frontend, segment(*from, *to, 4), 1);
  return {};
}

std::string stroke(HeadlessFrontend& frontend, const std::vector<std::string>& args, bool turn) {
  Studio& studio = frontend.studio();
  std::string problem;
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  double degrees = 0;
  std::size_t next = turn ? 1 : 3;
  if (turn) degrees = number(args, 0, "degrees", problem);
  else d = {number(args, 0, "dx", problem), number(args, 1, "dy", problem), number(args, 2, "dz", problem)};
  float wheel = 0;
  int steps = 8;
  for (; next < args.size() && problem.empty(); next += 2) {
    if (args[next] == "wheel" && !turn) wheel = static_cast<float>(number(args, next + 1, "wheel steps", problem));
    else if (args[next] == "steps") steps = std::max(1, static_cast<int>(number(args, next + 1, "steps", problem)));
    else problem = fmt::format("unknown option \"{}\" ({})", args[next], turn ? "steps" : "wheel, steps");
  }
  const std::optional<ImVec2> from = tool_on_screen(studio, problem);
  if (!problem.empty()) return problem;
  std::vector<ImVec2> points;
  studio.sculpt().drag_mode = turn ? SculptPanel::DragMode::kTurn : SculptPanel::DragMode::kMove;
  if (turn) {
    const float radius = 60;
    for (int i = 0; i <= steps; ++i) {
      const double angle = degrees * M_PI / 180 * i / steps;
      points.push_back({from->x + radius * static_cast<float>(std::cos(angle)), from->y + radius * static_cast<float>(std::sin(angle))});
    }
  } else {
    const std::optional<ImVec2> to = studio.viewport_point(*studio.sculpt().tool_center(studio) + d);
    if (!to) return "the tool's destination is not in view";
    points = segment(*from, *to, steps);
  }
  const std::uint64_t version = studio.document()->version();
  drag_through(frontend, points, 0, wheel);
  studio.sculpt().drag_mode = SculptPanel::DragMode::kMove;
  if (studio.document()->version() == version && studio.status().find("refused") == std::string::npos)
    return "the drag did not sculpt (not started on the part or the tool?): " + studio.status();
  return {};
}

}  // namespace

bool perform_sculpt_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                           std::string& problem) {
  Studio& studio = frontend.studio();
  if (!action.starts_with("sculpt-")) return false;
  if (!studio.document()) problem = "no design is open";
  else if (action == "sculpt-mode") problem = set_mode(studio, args);
  else if (action == "sculpt-tool") problem = set_tool(studio, args);
  else if (action == "sculpt-center") problem = set_center(studio, args);
  else if (action == "sculpt-view") problem = set_view(studio, args);
  else if (action == "sculpt-place") problem = place(frontend, args);
  else if (action == "sculpt-drag") problem = stroke(frontend, args, false);
  else if (action == "sculpt-turn") problem = stroke(frontend, args, true);
  else return false;
  frontend.run_frame();
  return true;
}

}  // namespace reconfig::studio
