#include "sculpt_script.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "axis_angle.h"
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

/// sculpt-rotation AX AY AZ DEGREES: the tool's rotation (the inspector's tool axis and degrees).
std::string set_rotation(Studio& studio, const std::vector<std::string>& args) {
  std::string problem;
  const Eigen::Vector3d axis(number(args, 0, "axis x", problem), number(args, 1, "axis y", problem),
                             number(args, 2, "axis z", problem));
  const AxisAngle rotation{axis, number(args, 3, "degrees", problem)};
  const std::optional<Eigen::Quaterniond> q = problem.empty() ? rotation_of(rotation) : std::nullopt;
  if (!q) return problem.empty() ? "the rotation axis must not be zero" : problem;
  studio.sculpt().settings().rotation = *q;
  return {};
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

/// "the drag did not sculpt" unless the document changed since `version` or a move was refused.
std::string sculpted(Studio& studio, std::uint64_t version) {
  if (studio.document()->version() == version && studio.status().find("refused") == std::string::npos)
    return "the drag did not sculpt (not started on the part or the tool?): " + studio.status();
  return {};
}

/// `p` at a whole pixel, as ImGui takes the mouse (it floors the position).
ImVec2 whole_pixel(const ImVec2& p) { return {std::floor(p.x), std::floor(p.y)}; }

/// Where ring `axis` is drawn in the viewport (at a whole pixel) farthest from the tool's
/// center `at`, under no other ring.
std::optional<ImVec2> ring_press(Studio& studio, int axis, const ImVec2& at) {
  const std::optional<ToolRings> rings = studio.sculpt().rings(studio);
  const Layout& layout = studio.layout();
  const auto in_view = [&](const ImVec2& p) {
    return p.x > layout.viewport_min.x && p.x < layout.viewport_max.x && p.y > layout.viewport_min.y &&
           p.y < layout.viewport_max.y;
  };
  std::optional<ImVec2> best;
  float farthest = 0;
  for (const Eigen::Vector3d& point : rings ? rings->ring(axis) : std::vector<Eigen::Vector3d>{})
    if (std::optional<ImVec2> p = studio.viewport_point(point);
        p && in_view(*p = whole_pixel(*p)) && studio.sculpt().ring_at(studio, *p) == axis) {
      const float distance = std::hypot(p->x - at.x, p->y - at.y);
      if (distance > farthest) farthest = distance, best = p;
    }
  return best;
}

/// A mouse path at whole pixels from `from` round `at` by `sweep` radians (pixel angles, y
/// down) in `steps` frames; of the pixels round its ideal end, it ends at the one whose angle
/// is nearest.
std::vector<ImVec2> sweep_path(const ImVec2& at, const ImVec2& from, double sweep, int steps) {
  const auto angle_of = [&](const ImVec2& p) { return std::atan2(p.y - at.y, p.x - at.x); };
  const double radius = std::hypot(from.x - at.x, from.y - at.y), start = angle_of(from);
  const auto miss = [&](const ImVec2& p) { return std::abs(std::remainder(angle_of(p) - start - sweep, 2 * M_PI)); };
  std::vector<ImVec2> points{from};
  for (int i = 1; i <= steps; ++i) {
    const double angle = start + sweep * i / steps;
    points.push_back(whole_pixel(
        {at.x + static_cast<float>(radius * std::cos(angle)), at.y + static_cast<float>(radius * std::sin(angle))}));
  }
  const ImVec2 end = points.back();
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy)
      if (const ImVec2 p(end.x + dx, end.y + dy); miss(p) < miss(points.back())) points.back() = p;
  return points;
}

/// sculpt-ring x|y|z DEGREES [steps N]: a left-drag from the ring round the tool's center on
/// screen, the way that turns the tool by DEGREES about the ring's axis (tool_rings.h).
std::string ring_drag(HeadlessFrontend& frontend, const std::vector<std::string>& args) {
  Studio& studio = frontend.studio();
  if (args.size() != 2 && !(args.size() == 4 && args[2] == "steps"))
    return "sculpt-ring x|y|z DEGREES [steps N]";
  const int axis = args[0] == "x" ? 0 : args[0] == "y" ? 1 : args[0] == "z" ? 2 : -1;
  if (axis < 0) return fmt::format("unknown ring \"{}\" (x, y, z)", args[0]);
  std::string problem;
  const double radians = number(args, 1, "degrees", problem) * M_PI / 180;
  // Less than a half turn a frame, so each frame's sweep is the one meant.
  const int steps = std::max({1, args.size() == 4 ? static_cast<int>(number(args, 3, "steps", problem)) : 8,
                              static_cast<int>(std::ceil(std::abs(radians) / (M_PI / 2)))});
  const std::optional<ImVec2> at = tool_on_screen(studio, problem);
  if (!problem.empty()) return problem;
  const std::optional<ImVec2> from = ring_press(studio, axis, *at);
  if (!from) return fmt::format("the tool's {} ring is seen edge-on or not in view", args[0]);
  // swept_turn's sign, undone: a positive screen sweep turns about an axis pointing away.
  const bool away = studio.sculpt().rings(studio)->axes.col(axis).dot(studio.camera().forward()) >= 0;
  const double sweep = away ? radians : -radians;
  const std::vector<ImVec2> points = sweep_path(*at, *from, sweep, steps);
  const std::uint64_t version = studio.document()->version();
  drag_through(frontend, points, 0);
  return sculpted(studio, version);
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
  return sculpted(studio, version);
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
  else if (action == "sculpt-rotation") problem = set_rotation(studio, args);
  else if (action == "sculpt-view") problem = set_view(studio, args);
  else if (action == "sculpt-place") problem = place(frontend, args);
  else if (action == "sculpt-drag") problem = stroke(frontend, args, false);
  else if (action == "sculpt-turn") problem = stroke(frontend, args, true);
  else if (action == "sculpt-ring") problem = ring_drag(frontend, args);
  else return false;
  frontend.run_frame();
  return true;
}

}  // namespace reconfig::studio
