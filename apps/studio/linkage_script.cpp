// The linkage panel's script actions (docs/studio.md, "Script actions"): they aim at joints and
// curves where the panel draws them and drag there with the mouse, as a user would.

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "script.h"

namespace reconfig::studio {
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

double number(const std::vector<std::string>& args, std::size_t i, const char* what) {
  if (i >= args.size()) fail(fmt::format("missing {}", what));
  if (const std::optional<double> value = script_number(args[i])) return *value;
  fail(fmt::format("{} must be a number, not \"{}\"", what, args[i]));
}

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

class LinkageActions {
 public:
  explicit LinkageActions(HeadlessFrontend& frontend) : frontend_(frontend) {}

  void perform(const std::string& action, const std::vector<std::string>& args) {
    if (action == "linkage-open") {
      if (args.empty()) fail("linkage-open needs a transition or a linkage file");
      open(args[0]);
    } else if (action == "linkage-keep") {
      keep(args);
    } else if (action == "linkage-angle") {
      if (!panel().lone()) fail("linkage-angle sets the motor of a linkage opened alone (scrub a transition's)");
      panel().set_lone_angle(radians(number(args, 0, "motor angle in degrees")));
      frontend_.run_frame();
    } else if (action == "linkage-drag-joint") {
      drag_joint(args);
    } else if (action == "linkage-drag-curve") {
      drag_curve(args);
    } else if (action == "linkage-target-curve") {
      if (args.size() < 6) fail("linkage-target-curve needs TRANSITION|- POINT SCALE DEGREES TX TY");
      select(args[0]);
      const int point = tracking_point(args[1]);
      panel().editor().transform_target(point, number(args, 2, "scale"), radians(number(args, 3, "degrees")),
                                        {number(args, 4, "tx"), number(args, 5, "ty")});
      panel().fit(frontend_.studio());
      frontend_.run_frame();
    } else if (action == "linkage-enclosure") {
      enclosure(args);
    } else if (action == "linkage-expect-motion") {
      expect_motion(args);
    } else if (action == "linkage-expect-deviation") {
      expect_deviation(args);
    } else {
      fail(fmt::format("unknown action \"{}\"", action));
    }
  }

 private:
  LinkagePanel& panel() { return frontend_.studio().linkage_panel(); }
  const LinkageEditor& editor() { return panel().editor(); }

  void open(const std::string& what) {
    Studio& studio = frontend_.studio();
    const int transition = studio.document() ? studio.document()->scene().find_transition(what) : -1;
    const bool opened = transition >= 0 ? panel().open_drive(studio, transition) : panel().open_file(studio, what);
    if (!opened) fail(studio.status());
    frontend_.run_frame();
  }

  /// `-`: the linkage opened alone; else a transition whose drive the panel shows.
  void select(const std::string& what) {
    if (what == "-") {
      if (!panel().lone()) fail("no linkage is open alone");
    } else if (panel().transition(frontend_.studio()) < 0 ||
               frontend_.studio().document()->scene().transitions[panel().transition(frontend_.studio())].name != what) {
      open(what);
    }
    frontend_.run_frame();  // the canvas is laid out
  }

  int tracking_point(const std::string& name) {
    const auto& points = editor().linkage().tracking_points;
    for (std::size_t p = 0; p < points.size(); ++p)
      if (points[p].name == name || editor().linkage().joints[points[p].joint].name == name) return static_cast<int>(p);
    fail(fmt::format("no tracking point \"{}\"", name));
  }

  /// linkage-keep POINT… | none: ticks exactly these tracking points' "keep" boxes.
  void keep(const std::vector<std::string>& names) {
    if (editor().empty()) fail("the linkage panel shows no linkage");
    std::vector<bool> flags(editor().linkage().tracking_points.size(), false);
    for (const std::string& name : names)
      if (name != "none") flags[tracking_point(name)] = true;
    panel().editor().keep = flags;
  }

  /// linkage-drag-joint TRANSITION|- JOINT DX DY [keep=P,Q|none]
  void drag_joint(const std::vector<std::string>& args) {
    if (args.size() < 4) fail("linkage-drag-joint needs TRANSITION|- JOINT DX DY [keep=POINT,...]");
    select(args[0]);
    for (std::size_t i = 4; i < args.size(); ++i) {
      if (!args[i].starts_with("keep=")) fail(fmt::format("unknown option \"{}\" (keep=POINT,...)", args[i]));
      std::vector<std::string> names;
      for (std::size_t from = 5, comma; from <= args[i].size(); from = comma + 1) {
        comma = std::min(args[i].find(',', from), args[i].size());
        names.push_back(args[i].substr(from, comma - from));
      }
      keep(names);
    }
    const int joint = editor().linkage().find_joint(args[1]);
    if (joint < 0) fail(fmt::format("no joint \"{}\"", args[1]));
    const Eigen::Vector2d offset(number(args, 2, "dx"), number(args, 3, "dy"));
    Eigen::Matrix2Xd X;
    if (!panel().joints_now(frontend_.studio(), X)) fail("the linkage cannot be drawn at this motor angle");
    drag(panel().screen_point(X.col(joint)), panel().screen_point(X.col(joint) + offset));
  }

  /// linkage-drag-curve TRANSITION|- POINT INDEX DX DY [radius=R]
  void drag_curve(const std::vector<std::string>& args) {
    if (args.size() < 5) fail("linkage-drag-curve needs TRANSITION|- POINT INDEX DX DY [radius=R]");
    select(args[0]);
    const int point = tracking_point(args[1]);
    const int index = static_cast<int>(number(args, 2, "sample index"));
    const Eigen::Vector2d offset(number(args, 3, "dx"), number(args, 4, "dy"));
    if (args.size() > 5) {
      if (!args[5].starts_with("radius=")) fail(fmt::format("unknown option \"{}\" (radius=R)", args[5]));
      panel().soft_radius = number({args[5].substr(7)}, 0, "radius");
    }
    const auto& curve = editor().targets[point] ? *editor().targets[point] : editor().curve(point);
    if (index < 0 || index >= static_cast<int>(curve.size()))
      fail(fmt::format("no sample {} (the curve has {})", index, curve.size()));
    const Eigen::Vector2d at = curve[index];
    drag(panel().screen_point(at), panel().screen_point(at + offset));
  }

  /// linkage-enclosure TRANSITION|- XMIN YMIN XMAX YMAX | off
  void enclosure(const std::vector<std::string>& args) {
    if (args.size() < 2) fail("linkage-enclosure needs TRANSITION|- XMIN YMIN XMAX YMAX, or off");
    select(args[0]);
    if (args[1] == "off") {
      panel().editor().enclosure.reset();
      return;
    }
    const Eigen::Vector2d lo(number(args, 1, "xmin"), number(args, 2, "ymin")),
        hi(number(args, 3, "xmax"), number(args, 4, "ymax"));
    if (!(lo.array() < hi.array()).all()) fail("the enclosure needs XMIN < XMAX and YMIN < YMAX");
    panel().editor().enclosure = std::pair{lo, hi};
    panel().fit(frontend_.studio());
    frontend_.run_frame();
  }

  void expect_motion(const std::vector<std::string>& args) {
    if (editor().empty()) fail("the linkage panel shows no linkage");
    if (args.empty() || (args[0] != "full" && args[0] != "rocks")) fail("linkage-expect-motion full|rocks");
    if (editor().range().full_rotation != (args[0] == "full"))
      fail(fmt::format("expected the crank to {}, its motion: {}", args[0] == "full" ? "turn fully" : "rock",
                       editor().range().describe()));
  }

  /// linkage-expect-deviation POINT MAX [target]: the point's motion now is within MAX of its
  /// curve when the panel was opened (or of its target curve).
  void expect_deviation(const std::vector<std::string>& args) {
    if (args.size() < 2) fail("linkage-expect-deviation needs POINT MAX [target]");
    const int point = tracking_point(args[0]);
    const double limit = number(args, 1, "largest deviation");
    const bool target = args.size() > 2 && args[2] == "target";
    if (target && !editor().targets[point]) fail(fmt::format("{} has no target curve", args[0]));
    const double deviation =
        target ? LinkageEditor::deviation(editor().linkage(), point, editor().sample_angles(), *editor().targets[point])
               : LinkageEditor::deviation(editor().linkage(), point, panel().opened_angles(), panel().opened_curves()[point]);
    if (!(deviation <= limit))
      fail(fmt::format("{} deviates {:.6g} from its {} curve (more than {})", args[0], deviation,
                       target ? "target" : "opened", limit));
  }

  void drag(ImVec2 from, ImVec2 to) {
    std::vector<ImVec2> points;
    for (int i = 0; i <= 12; ++i) {
      const float f = i / 12.0f;
      points.push_back({from.x + f * (to.x - from.x), from.y + f * (to.y - from.y)});
    }
    drag_through(frontend_, points);
  }

  HeadlessFrontend& frontend_;
};

}  // namespace

void run_linkage_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args) {
  LinkageActions(frontend).perform(action, args);
}

}  // namespace reconfig::studio
