#include "script.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "authoring_script.h"
#include "handle_drag.h"
#include "keys.h"
#include "sculpt_script.h"
#include "shaping_script.h"
#include "reconfig/render/image.h"

namespace reconfig::studio {

std::optional<double> script_number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

ScriptError::ScriptError(const std::string& file, int line, const std::string& message)
    : std::runtime_error(fmt::format("{}:{}: {}", file, line, message)) {}

std::vector<ImVec2> segment(ImVec2 a, ImVec2 b, int steps) {
  std::vector<ImVec2> points;
  for (int i = 0; i <= steps; ++i) {
    const float f = static_cast<float>(i) / steps;
    points.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
  }
  return points;
}

void drag_through(HeadlessFrontend& frontend, const std::vector<ImVec2>& points, int button, float wheel) {
  SimulatedInput& input = frontend.input();
  input.mouse = points.front();
  frontend.run_frame();  // hover first: ImGui sees the press where the mouse already is
  input.buttons[button] = true;
  frontend.run_frame();
  for (std::size_t i = 1; i < points.size(); ++i) {
    input.mouse = points[i];
    if (i == points.size() / 2) input.wheel = wheel;
    frontend.run_frame();
  }
  input.buttons[button] = false;
  frontend.run_frame();
  frontend.run_frame();
}

namespace {

GizmoHandle parse_handle(const std::string& name) {
  static const std::pair<const char*, GizmoHandle> kHandles[] = {
      {"move-x", GizmoHandle::kMoveX},     {"move-y", GizmoHandle::kMoveY},     {"move-z", GizmoHandle::kMoveZ},
      {"rotate-x", GizmoHandle::kRotateX}, {"rotate-y", GizmoHandle::kRotateY}, {"rotate-z", GizmoHandle::kRotateZ}};
  for (const auto& [label, handle] : kHandles)
    if (name == label) return handle;
  return GizmoHandle::kNone;
}

class Runner {
 public:
  Runner(HeadlessFrontend& frontend, std::string label) : frontend_(frontend), label_(std::move(label)) {}

  void run(const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      ++line_;
      if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
      std::istringstream words(line);
      std::string action;
      if (!(words >> action)) continue;
      std::vector<std::string> args;
      for (std::string word; words >> word;) args.push_back(word);
      perform(action, args);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw ScriptError(label_, line_, message); }

  double number(const std::vector<std::string>& args, std::size_t i, const char* what) const {
    if (i >= args.size()) fail(fmt::format("missing {}", what));
    if (const std::optional<double> value = script_number(args[i])) return *value;
    fail(fmt::format("{} must be a number, not \"{}\"", what, args[i]));
  }

  Studio& studio() { return frontend_.studio(); }

  /// `options` with the script's `KEY=VALUE` collision settings applied.
  collision::DetectorOptions with_settings(collision::DetectorOptions options, const std::vector<std::string>& settings) const {
    for (const std::string& setting : settings) {
      const auto equals = setting.find('=');
      const std::string key = setting.substr(0, equals), value = equals == std::string::npos ? "" : setting.substr(equals + 1);
      const std::vector<std::string> word{value};
      if (key == "tolerance") {
        options.tolerance = number(word, 0, "tolerance");
      } else if (key == "box-resolution") {
        options.box_resolution = number(word, 0, "box-resolution");
      } else if (key == "frame") {
        options.frame = number(word, 0, "frame");
      } else if (key == "dop") {
        const double halfspaces = number(word, 0, "dop");
        const auto family = halfspaces == std::floor(halfspaces) ? collision::dop_family(static_cast<int>(halfspaces)) : std::nullopt;
        if (!family) fail(fmt::format("dop must be {}, not \"{}\"", scene::dop_halfspace_choices(), value));
        options.dop = *family;
      } else if (key == "conservative" && (value == "on" || value == "off")) {
        options.conservative = value == "on";
      } else {
        fail(fmt::format("unknown collision setting \"{}\" (tolerance=, dop={}, box-resolution=, frame=, "
                         "conservative=on|off)", setting, fmt::join(scene::kDopHalfspaces, "|")));
      }
    }
    return options;
  }

  const scene::Reconfigurable& scene() {
    if (!studio().document()) fail("no design is open");
    return studio().document()->scene();
  }

  int transition_named(const std::string& name) {
    const int index = scene().find_transition(name);
    if (index < 0) fail(fmt::format("no transition \"{}\"", name));
    return index;
  }

  const collision::TransitionSnapshot& current_collisions() {
    const auto snapshot = studio().collisions();
    const int transition = studio().active_transition();
    if (!snapshot || transition < 0) fail("no transition is open");
    for (const auto& t : snapshot->transitions)
      if (t.transition == transition) {
        snapshot_ = snapshot;
        return t;
      }
    fail("the collision service has no result for the open transition yet (wait-collisions first)");
  }

  /// Automatic resolution of the open transition, waited for (one undoable edit).
  void resolve_automatically(double seconds, bool move_states) {
    if (!studio().start_auto_resolve(true, move_states))
      fail("automatic resolution needs an open transition (and none running)");
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(seconds * 1000));
    while (studio().auto_resolving()) {
      if (std::chrono::steady_clock::now() > deadline) {
        studio().cancel_auto_resolve();
        fail(fmt::format("automatic resolution did not finish within {} s", seconds));
      }
      frontend_.run_frame();
    }
  }

  void click(ImVec2 at, int button = 0) { drag_through(frontend_, {at}, button); }

  /// Until the picture-in-picture's view search under way, if any, ended (60 s at most).
  void wait_for_pip() {
    if (!frontend_.run_while_pip_searches(std::chrono::steady_clock::now() + std::chrono::seconds(60)))
      fail("the picture-in-picture found no view within 60 s");
  }

  void press_key(const std::string& chord) {
    SimulatedInput& input = frontend_.input();
    std::string rest = chord;
    bool ctrl = false, shift = false;
    for (std::size_t plus; (plus = rest.find('+')) != std::string::npos; rest.erase(0, plus + 1)) {
      const std::string modifier = rest.substr(0, plus);
      if (modifier == "ctrl") ctrl = true;
      else if (modifier == "shift") shift = true;
      else fail(fmt::format("unknown modifier \"{}\" (ctrl, shift)", modifier));
    }
    const int code = keys::from_name(rest.c_str());
    if (code < 0) fail(fmt::format("unknown key \"{}\"", rest));
    input.ctrl = ctrl;
    input.shift = shift;
    input.keys_down.insert(code);
    frontend_.run_frame();
    input.keys_down.erase(code);
    input.ctrl = input.shift = false;
    frontend_.run_frame();
  }

  /// sculpt PART sphere|box|capsule|ellipsoid SX SY SZ COATING CX CY CZ (translate DX DY DZ |
  /// scale F | rotate AX AY AZ DEGREES) [mirror x|y|z]
  void sculpt(const std::vector<std::string>& args) {
    if (args.size() < 10) fail("sculpt needs PART SHAPE SX SY SZ COATING CX CY CZ and a stroke");
    const int part = scene().find_part(args[0]);
    if (part < 0) fail(fmt::format("no part \"{}\"", args[0]));
    Studio::SculptSettings settings;
    const std::vector<std::string> shapes = {"sphere", "box", "capsule", "ellipsoid"};
    const auto shape = std::find(shapes.begin(), shapes.end(), args[1]);
    if (shape == shapes.end()) fail(fmt::format("unknown tool \"{}\" (sphere, box, capsule, ellipsoid)", args[1]));
    settings.shape = static_cast<int>(shape - shapes.begin());
    settings.size = {number(args, 2, "size x"), number(args, 3, "size y"), number(args, 4, "size z")};
    settings.coating = number(args, 5, "coating");
    settings.center = {number(args, 6, "center x"), number(args, 7, "center y"), number(args, 8, "center z")};
    std::size_t next = 10;
    if (args[9] == "translate") {
      settings.stroke = 0;
      settings.translation = {number(args, 10, "dx"), number(args, 11, "dy"), number(args, 12, "dz")};
      next = 13;
    } else if (args[9] == "scale") {
      settings.stroke = 1;
      settings.factor = number(args, 10, "factor");
      next = 11;
    } else if (args[9] == "rotate") {
      settings.stroke = 2;
      settings.axis = {number(args, 10, "axis x"), number(args, 11, "axis y"), number(args, 12, "axis z")};
      settings.degrees = number(args, 13, "degrees");
      next = 14;
    } else {
      fail(fmt::format("unknown stroke \"{}\" (translate, scale, rotate)", args[9]));
    }
    if (next < args.size()) {
      if (args[next] != "mirror" || next + 1 >= args.size() || args[next + 1].size() != 1 ||
          args[next + 1][0] < 'x' || args[next + 1][0] > 'z')
        fail("after the stroke: mirror x|y|z");
      settings.mirror = args[next + 1][0] - 'x';
    }
    studio().select_part(part);
    studio().sculpt_settings() = settings;
    if (!studio().sculpt_selected_part()) fail(studio().status());
    frontend_.run_frame();
  }

  void perform(const std::string& action, const std::vector<std::string>& args) {
    if (action.starts_with("linkage-")) {  // the linkage panel's actions (linkage_script.cpp)
      try {
        run_linkage_action(frontend_, action, args);
      } catch (const std::runtime_error& error) {
        fail(error.what());
      }
      return;
    }
    SimulatedInput& input = frontend_.input();
    if (action == "frames") {
      const int count = static_cast<int>(number(args, 0, "frame count"));
      for (int i = 0; i < count; ++i) frontend_.run_frame();
    } else if (action == "open") {
      if (args.empty()) fail("open needs a file");
      if (!studio().open(args[0])) fail(studio().status());
      frontend_.run_frame();
    } else if (action == "wait-collisions") {
      const double seconds = args.empty() ? 60 : number(args, 0, "timeout in seconds");
      if (!frontend_.run_until_collisions_current(std::chrono::milliseconds(static_cast<long>(seconds * 1000))))
        fail(fmt::format("collision detection did not finish within {} s", seconds));
    } else if (action == "collision-settings") {
      const collision::DetectorOptions options = with_settings(studio().detector_options(), args);
      if (!studio().set_detector_options(options)) fail(studio().status());
      frontend_.run_frame();
    } else if (action == "expect-collision-settings") {
      const collision::DetectorOptions& now = studio().detector_options();
      const collision::DetectorOptions expected = with_settings(now, args);
      if (expected.tolerance != now.tolerance || expected.dop != now.dop || expected.box_resolution != now.box_resolution ||
          expected.frame != now.frame || expected.conservative != now.conservative)
        fail(fmt::format("the collision settings are not {}: the status says \"{}\"", fmt::join(args, " "),
                         studio().status()));
    } else if (action == "mouse") {
      input.mouse = {static_cast<float>(number(args, 0, "x")), static_cast<float>(number(args, 1, "y"))};
      frontend_.run_frame();
    } else if (action == "click") {
      click({static_cast<float>(number(args, 0, "x")), static_cast<float>(number(args, 1, "y"))});
    } else if (action == "drag") {
      const ImVec2 a{static_cast<float>(number(args, 0, "x0")), static_cast<float>(number(args, 1, "y0"))};
      const ImVec2 b{static_cast<float>(number(args, 2, "x1")), static_cast<float>(number(args, 3, "y1"))};
      drag_through(frontend_, segment(a, b, 8));
    } else if (action == "scroll") {
      input.wheel = static_cast<float>(number(args, 0, "wheel steps"));
      frontend_.run_frame();
    } else if (action == "key") {
      if (args.empty()) fail("key needs a key name, e.g. space, ctrl+z, ctrl+shift+z, i, delete");
      press_key(args[0]);
    } else if (action == "click-part") {
      if (args.empty()) fail("click-part needs a part name");
      const int part = scene().find_part(args[0]);
      if (part < 0) fail(fmt::format("no part \"{}\"", args[0]));
      const ImVec2 at = part_point(part);
      click(at);
      const int picked = studio().selected_part();
      if (picked != part)
        fail(fmt::format("click-part {}: the click at ({:.0f}, {:.0f}) selected {} ({})", args[0], at.x, at.y,
                         picked < 0 ? "nothing" : scene().parts[picked].name,
                         picked < 0 ? "the part is not drawn there" : "it is in front of the part"));
    } else if (action == "click-edge") {
      if (args.empty()) fail("click-edge needs a transition name");
      const auto at = studio().graph_edge_point(transition_named(args[0]));
      if (!at) fail("the state graph is not drawn");
      click(*at);
    } else if (action == "scrub") {
      click(studio().timeline_point(std::clamp(number(args, 0, "time"), 0.0, 1.0)));
    } else if (action == "drag-gizmo") {
      if (args.empty()) fail("drag-gizmo needs a handle (move-x … rotate-z) and an amount");
      drag_gizmo(args[0], number(args, 1, "amount (world units or degrees)"));
    } else if (action == "drag-key") {
      drag_key(args);
    } else if (action == "drag-handle") {
      drag_handle(args);
    } else if (action == "wait-hint") {
      const double seconds = args.empty() ? 60 : number(args, 0, "timeout in seconds");
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long>(seconds * 1000));
      while (studio().hint_pending()) {
        if (std::chrono::steady_clock::now() > deadline) fail(fmt::format("the hint did not arrive within {} s", seconds));
        frontend_.run_frame();
      }
    } else if (action == "slide-hint") {
      if (!studio().slide_along_hint(number(args, 0, "amount along the hint"))) fail(studio().status());
      frontend_.run_frame();
    } else if (action == "sculpt") {
      sculpt(args);
    } else if (action == "resolve-auto") {
      const bool move_states = !args.empty() && args.back() == "move-states";
      const bool timed = args.size() > (move_states ? 1u : 0u);
      resolve_automatically(timed ? number(args, 0, "timeout in seconds") : 120, move_states);
    } else if (action == "expect-collisions") {
      const auto& collisions = current_collisions();
      const int expected = static_cast<int>(number(args, 0, "interval count"));
      if (static_cast<int>(collisions.intervals.size()) != expected)
        fail(fmt::format("expected {} collision intervals in the timeline, it shows {}", expected,
                         collisions.intervals.size()));
    } else if (action == "expect-collision-at" || action == "expect-free-at") {
      const double t = number(args, 0, "time");
      bool colliding = false;
      for (const auto& interval : current_collisions().intervals) colliding |= interval.t0 <= t && t <= interval.t1;
      if (colliding != (action == "expect-collision-at"))
        fail(fmt::format("expected {} at t = {}", colliding ? "no collision" : "a collision", t));
    } else if (action == "expect-selected") {
      const int selected = studio().selected_part();
      const std::string name = selected >= 0 ? scene().parts[selected].name : "none";
      if (args.empty() || name != args[0]) fail(fmt::format("expected {} selected, not {}", args.empty() ? "?" : args[0], name));
    } else if (action == "expect-time") {
      const double expected = number(args, 0, "time"), tolerance = args.size() > 1 ? number(args, 1, "tolerance") : 1e-3;
      if (std::abs(studio().time() - expected) > tolerance)
        fail(fmt::format("expected time {}, the timeline shows {:.4f}", expected, studio().time()));
    } else if (action == "expect-transition") {
      const int active = studio().active_transition();
      if (args.empty() || active != transition_named(args[0]))
        fail(fmt::format("expected transition {} open", args.empty() ? "?" : args[0]));
    } else if (action == "expect-status") {
      std::string text;
      for (const auto& word : args) text += (text.empty() ? "" : " ") + word;
      if (studio().status().find(text) == std::string::npos)
        fail(fmt::format("expected the status to say \"{}\", it says \"{}\"", text, studio().status()));
    } else if (action == "click-pip") {
      wait_for_pip();
      if (!studio().pip().target()) fail("no picture-in-picture is open");
      const ImVec2 lo = studio().pip().image_min(), hi = studio().pip().image_max();
      click({(lo.x + hi.x) / 2, (lo.y + hi.y) / 2});
    } else if (action == "expect-pip") {
      wait_for_pip();
      const auto& target = studio().pip().target();
      std::string shown = "none";
      if (target) {
        shown.clear();
        for (int part : target->interval.parts) shown += (shown.empty() ? "" : " ") + scene().parts[part].name;
      }
      std::string expected;
      for (const auto& word : args) expected += (expected.empty() ? "" : " ") + word;
      if (expected.empty()) expected = "none";
      if (shown != expected) fail(fmt::format("expected the picture-in-picture on {}, it shows {}", expected, shown));
    } else if (action == "screenshot") {
      if (args.empty()) fail("screenshot needs a file");
      frontend_.run_frame();
      render::write_png(args[0], frontend_.screenshot());
    } else if (action == "save") {
      const bool saved = args.empty() ? studio().save() : studio().save_as(args[0]);
      if (!saved) fail(studio().status());
    } else if (std::string sculpt_failure; perform_sculpt_action(frontend_, action, args, sculpt_failure)) {
      if (!sculpt_failure.empty()) fail(sculpt_failure);
    } else if (std::string problem; perform_shaping_action(frontend_, action, args, problem)) {
      if (!problem.empty()) fail(problem);
    } else if (!run_authoring_action(frontend_, action, args, [this](const std::string& why) { fail(why); })) {
      fail(fmt::format("unknown action \"{}\"", action));
    }
  }

  /// Where part `part`'s center (the mean of its posed vertices) is drawn; another part may be
  /// in front of it there, which `click-part` reports.
  ImVec2 part_point(int part) {
    const Eigen::MatrixX3d V = studio().active_transition() >= 0
                                   ? scene().posed_vertices(studio().active_transition(), part, studio().time())
                                   : Eigen::MatrixX3d(scene().parts[part].mesh.V);
    const Eigen::Vector3d center = V.colwise().mean().transpose();
    const auto at = studio().viewport_point(center);
    if (!at) fail("the part is behind the camera");
    return *at;
  }

  void drag_gizmo(const std::string& name, double amount) {
    const GizmoHandle handle = parse_handle(name);
    if (handle == GizmoHandle::kNone) fail(fmt::format("unknown handle \"{}\"", name));
    const auto gizmo = studio().gizmo();
    if (!gizmo) fail("no gizmo: select a part first");
    const Eigen::Vector3d axis = handle_axis(handle);
    Eigen::Vector3d from, to;
    if (!is_rotation(handle)) {
      from = gizmo->center + 0.7 * gizmo->arrow_length * axis;
      to = from + amount * axis;
    } else {
      // Along the ring, starting at the point facing the camera most.
      const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
      const Eigen::Vector3d toward = -studio().camera().forward();
      const double start = std::atan2(toward.dot(v), toward.dot(u));
      from = gizmo->center + gizmo->ring_radius * (std::cos(start) * u + std::sin(start) * v);
      const double end = start + amount * M_PI / 180;
      to = gizmo->center + gizmo->ring_radius * (std::cos(end) * u + std::sin(end) * v);
    }
    const auto a = studio().viewport_point(from), b = studio().viewport_point(to);
    if (!a || !b) fail("the gizmo is off screen");
    drag_through(frontend_, segment(*a, *b, 10));
  }

  void drag_key(const std::vector<std::string>& args) {
    if (args.size() < 3) fail("drag-key needs: translation|rotation INDEX TIME");
    const bool translation = args[0] == "translation";
    if (!translation && args[0] != "rotation") fail("drag-key: the row is translation or rotation");
    const int index = static_cast<int>(number(args, 1, "key index"));
    const double to = number(args, 2, "time");
    const scene::KeyframedTrack* track = selected_track("drag-key");
    const int count = static_cast<int>(translation ? track->translation.size() : track->rotation.size());
    if (index < 0 || index >= count) fail(fmt::format("no key {} (the row has {})", index, count));
    const double from = translation ? track->translation[index].time : track->rotation[index].time;
    const float y = translation ? studio().layout().translation_row_y : studio().layout().rotation_row_y;
    drag_through(frontend_, segment({studio().timeline_point(from).x, y}, {studio().timeline_point(to).x, y}, 8));
  }

  /// Drags the end of the in or out handle of a translation key of the selected part by a
  /// world offset, as drawn: from where the end is drawn to where end + offset is.
  void drag_handle(const std::vector<std::string>& args) {
    if (args.size() < 5) fail("drag-handle needs: INDEX in|out DX DY DZ");
    const int index = static_cast<int>(number(args, 0, "key index"));
    if (args[1] != "in" && args[1] != "out") fail("drag-handle: the handle is in or out");
    const Eigen::Vector3d offset(number(args, 2, "dx"), number(args, 3, "dy"), number(args, 4, "dz"));
    const scene::KeyframedTrack* track = selected_track("drag-handle");
    const int count = static_cast<int>(track->translation.size());
    if (index < 0 || index >= count) fail(fmt::format("no translation key {} (the track has {})", index, count));
    const Eigen::Vector3d end =
        handle_end(track->translation[index], scene().parts[studio().selected_part()].center, args[1] == "out");
    const auto a = studio().viewport_point(end), b = studio().viewport_point(end + offset);
    if (!a || !b) fail("the handle is off screen");
    drag_through(frontend_, segment(*a, *b, 8));
  }

  /// The selected part's keyframed track in the open transition (`action` needs one).
  const scene::KeyframedTrack* selected_track(const char* action) {
    if (studio().selected_part() < 0 || studio().active_transition() < 0)
      fail(fmt::format("{} needs a selected part and an open transition", action));
    const scene::KeyframedTrack* track = studio().selected_keyframed_track();
    if (!track) fail("the selected part has no keyframed track here");
    return track;
  }

  HeadlessFrontend& frontend_;
  std::string label_;
  int line_ = 0;
  std::shared_ptr<const collision::CollisionSnapshot> snapshot_;
};

}  // namespace

void run_script(HeadlessFrontend& frontend, const std::string& script_text, const std::string& label) {
  Runner(frontend, label).run(script_text);
}

}  // namespace reconfig::studio
