// Script actions that author a design: each calls the studio action a menu item calls, then
// runs a frame. A refusal fails the script, except under `expect-refused`, which wants one
// (with the status bar saying so and the design untouched).

#include "authoring_script.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>

#include "script.h"
#include "reconfig/scene/part_edits.h"
#include "reconfig/scene/scene_file.h"
#include "reconfig/scene/state_edits.h"

namespace reconfig::studio {
namespace {

namespace fs = std::filesystem;

class AuthoringActions {
 public:
  AuthoringActions(HeadlessFrontend& frontend, const std::function<void(const std::string&)>& fail)
      : frontend_(frontend), fail_(fail) {}

  /// Runs `action`; false when it is none of ours. The edits' results come back as
  /// "" (done) or the status line's refusal.
  bool run(const std::string& action, const std::vector<std::string>& args) {
    if (action == "expect-refused") {
      expect_refused(args);
      return true;
    }
    if (action == "expect-count" || action == "expect-name" || action == "expect-no-name") {
      expect(action, args);
      return true;
    }
    const auto done = perform(action, args);
    if (!done) return false;
    if (!*done) fail_(studio().status());
    frontend_.run_frame();
    return true;
  }

 private:
  Studio& studio() { return frontend_.studio(); }

  [[noreturn]] void fail(const std::string& message) {
    fail_(message);
    throw std::logic_error("fail returned");  // fail_ throws
  }

  const scene::Reconfigurable& scene() {
    if (!studio().document()) fail("no design is open (new FILE or open FILE first)");
    return studio().document()->scene();
  }

  void need(const std::vector<std::string>& args, std::size_t count, const char* usage) {
    if (args.size() < count) fail(fmt::format("usage: {}", usage));
  }

  double number(const std::vector<std::string>& args, std::size_t i, const char* what) {
    if (i >= args.size()) fail(fmt::format("missing {}", what));
    if (const std::optional<double> value = script_number(args[i])) return *value;
    fail(fmt::format("{} must be a number, not \"{}\"", what, args[i]));
  }

  int index_of(const std::string& kind, const std::string& name) {
    const int index = kind == "part" ? scene().find_part(name) : kind == "state" ? scene().find_state(name)
                                                                                 : scene().find_transition(name);
    if (index < 0) fail(fmt::format("no {} \"{}\"", kind, name));
    return index;
  }

  std::optional<scene::Choreography> choreography(const std::vector<std::string>& args, std::size_t i) {
    if (i >= args.size() || args[i] == "straight") return scene::Choreography::kStraight;
    if (args[i] == "screw") return scene::Choreography::kScrew;
    fail(fmt::format("the motion is straight or screw, not \"{}\"", args[i]));
  }

  scene::PartSource primitive(const std::vector<std::string>& args) {
    need(args, 3, "add-primitive NAME box SX SY SZ | cylinder RADIUS HEIGHT | sphere RADIUS");
    if (args[1] == "box") return scene::BoxPrimitive{{number(args, 2, "size x"), number(args, 3, "size y"), number(args, 4, "size z")}};
    if (args[1] == "cylinder") return scene::CylinderPrimitive{number(args, 2, "radius"), number(args, 3, "height")};
    if (args[1] == "sphere") return scene::SpherePrimitive{number(args, 2, "radius")};
    fail(fmt::format("unknown primitive \"{}\" (box, cylinder, sphere)", args[1]));
  }

  /// The edit `action` asks for, performed: true done, false refused (the status says why),
  /// nullopt when `action` is none of ours.
  std::optional<bool> perform(const std::string& action, const std::vector<std::string>& args) {
    Studio& s = studio();
    if (action == "new") {
      need(args, 1, "new FILE");
      return s.new_design(args[0]);
    }
    if (action == "undo") return s.undo();
    if (action == "redo") return s.redo();
    if (action == "import") {
      need(args, 1, "import FILE...");
      return s.import_meshes({args.begin(), args.end()});
    }
    if (action == "add-primitive") {
      if (!s.execute(scene::add_primitive_part(args.empty() ? "" : args[0], primitive(args)))) return false;
      s.select_part(scene().find_part(args[0]));
      return true;
    }
    if (action == "rename-part") {
      need(args, 2, "rename-part PART NEW_NAME");
      return s.execute(scene::rename_part(args[0], args[1]));
    }
    if (action == "recolor") {
      need(args, 2, "recolor PART R G B | none");
      if (args[1] == "none") return s.execute(scene::recolor_part(args[0], std::nullopt));
      return s.execute(scene::recolor_part(args[0], Eigen::Vector3d(number(args, 1, "red"), number(args, 2, "green"),
                                                                    number(args, 3, "blue"))));
    }
    if (action == "duplicate-part") {
      need(args, 2, "duplicate-part PART NEW_NAME");
      return s.execute(scene::duplicate_part(args[0], args[1]));
    }
    if (action == "delete-part") {
      need(args, 1, "delete-part PART [with-keys]");
      return s.execute(scene::delete_part(args[0], args.size() > 1 && args[1] == "with-keys"));
    }
    if (action == "replace-mesh") {
      need(args, 2, "replace-mesh PART FILE");
      return s.replace_part_mesh_from(index_of("part", args[0]), args[1]);
    }
    if (action == "add-state") {
      need(args, 1, "add-state NAME");
      return s.add_state_from_view(args[0]);
    }
    if (action == "rename-state") {
      need(args, 2, "rename-state STATE NEW_NAME");
      return s.execute(scene::rename_state(args[0], args[1]));
    }
    if (action == "delete-state") {
      need(args, 1, "delete-state STATE [with-transitions]");
      return s.execute(scene::delete_state(args[0], args.size() > 1 && args[1] == "with-transitions"));
    }
    if (action == "show-state") {
      need(args, 1, "show-state STATE");
      s.show_state(index_of("state", args[0]));
      return true;
    }
    if (action == "set-pose") return set_pose(args);
    if (action == "add-transition") {
      need(args, 3, "add-transition NAME FROM TO [straight|screw]");
      return s.add_transition_between(index_of("state", args[1]), index_of("state", args[2]), *choreography(args, 3),
                                      args[0]);
    }
    if (action == "drag-state") {
      need(args, 2, "drag-state FROM TO");
      drag_state(index_of("state", args[0]), index_of("state", args[1]));
      return true;
    }
    if (action == "rename-transition") {
      need(args, 2, "rename-transition TRANSITION NEW_NAME");
      return s.execute(scene::rename_transition(args[0], args[1]));
    }
    if (action == "delete-transition") {
      need(args, 1, "delete-transition TRANSITION");
      return s.execute(scene::delete_transition(args[0]));
    }
    if (action == "reverse-transition") {
      need(args, 1, "reverse-transition TRANSITION");
      return s.execute(scene::reverse_transition(args[0]));
    }
    if (action == "duplicate-transition") {
      need(args, 2, "duplicate-transition TRANSITION NEW_NAME");
      return s.execute(scene::duplicate_transition(args[0], args[1]));
    }
    if (action == "open-transition") {
      need(args, 1, "open-transition TRANSITION");
      s.open_transition(index_of("transition", args[0]));
      return true;
    }
    if (action == "set-handle") return set_handle(args);
    return std::nullopt;
  }

  /// set-pose STATE PART X Y Z [QW QX QY QZ]: the part's pose in the state (as the inspector's
  /// fields set it).
  bool set_pose(const std::vector<std::string>& args) {
    need(args, 5, "set-pose STATE PART X Y Z [QW QX QY QZ]");
    motion::Pose pose;
    pose.translation = {number(args, 2, "x"), number(args, 3, "y"), number(args, 4, "z")};
    if (args.size() > 5)
      pose.rotation = Eigen::Quaterniond(number(args, 5, "qw"), number(args, 6, "qx"), number(args, 7, "qy"),
                                         number(args, 8, "qz"));
    if (pose.rotation.norm() == 0) fail("the quaternion is zero");
    return studio().execute(scene::set_state_pose(args[0], args[1], pose));
  }

  /// set-handle TRANSITION PART KEY in|out X Y Z: where a translation key's handle lies (as
  /// the inspector's handle fields set it).
  bool set_handle(const std::vector<std::string>& args) {
    need(args, 7, "set-handle TRANSITION PART KEY in|out X Y Z");
    const int transition = index_of("transition", args[0]), part = index_of("part", args[1]);
    const scene::KeyframedTrack* track = scene().keyframed_track(transition, part);
    if (!track) fail(fmt::format("part \"{}\" has no keyframed track in \"{}\"", args[1], args[0]));
    const int key = static_cast<int>(number(args, 2, "key index"));
    if (key < 0 || key >= static_cast<int>(track->translation.size()))
      fail(fmt::format("no translation key {} (the track has {})", key, track->translation.size()));
    if (args[3] != "in" && args[3] != "out") fail("the handle is in or out");
    motion::TranslationKey value = track->translation[key];
    (args[3] == "in" ? value.in : value.out) = {number(args, 4, "x"), number(args, 5, "y"), number(args, 6, "z")};
    return studio().execute(scene::set_translation_key(args[0], args[1], key, value));
  }

  /// Drags the mouse from one state's node to another's in the state graph.
  void drag_state(int from, int to) {
    const auto a = studio().graph_state_point(from), b = studio().graph_state_point(to);
    if (!a || !b) fail("the state graph is not drawn");
    SimulatedInput& input = frontend_.input();
    input.mouse = *a;
    frontend_.run_frame();
    input.buttons[0] = true;
    frontend_.run_frame();
    for (int i = 1; i <= 8; ++i) {
      const float f = static_cast<float>(i) / 8;
      input.mouse = {a->x + f * (b->x - a->x), a->y + f * (b->y - a->y)};
      frontend_.run_frame();
    }
    input.buttons[0] = false;
    frontend_.run_frame();
  }

  /// expect-refused ACTION ARGS...: the action is refused, the status bar says why, and the
  /// design is as it was.
  void expect_refused(const std::vector<std::string>& args) {
    if (args.empty()) fail("expect-refused needs an action");
    const std::string before = design_text();
    const auto done = perform(args[0], {args.begin() + 1, args.end()});
    if (!done) fail(fmt::format("\"{}\" is no authoring action", args[0]));
    if (*done) fail(fmt::format("{} was not refused: the status says \"{}\"", fmt::join(args, " "), studio().status()));
    if (studio().status().empty()) fail("the refusal left the status bar empty");
    if (design_text() != before) fail("the refused edit changed the design");
    frontend_.run_frame();
  }

  /// The design as JSON (parts with edited meshes written by their names), for comparisons.
  std::string design_text() {
    if (!studio().document()) return "";
    scene::Reconfigurable copy = scene();
    for (scene::Part& part : copy.parts)
      if (std::holds_alternative<scene::EditedMesh>(part.source)) part.source = scene::MeshFile{"/edited/" + part.name};
    return scene::scene_to_json(copy, "/") + std::to_string(copy.parts.size());
  }

  /// expect-count parts|states|transitions N; expect-name / expect-no-name KIND NAME.
  void expect(const std::string& action, const std::vector<std::string>& args) {
    need(args, 2, "expect-count parts|states|transitions N, expect-name KIND NAME, expect-no-name KIND NAME");
    const std::map<std::string, std::string> kinds{{"parts", "part"}, {"states", "state"}, {"transitions", "transition"},
                                                   {"part", "part"},  {"state", "state"},  {"transition", "transition"}};
    const auto kind = kinds.find(args[0]);
    if (kind == kinds.end()) fail(fmt::format("unknown kind \"{}\" (part, state, transition)", args[0]));
    const scene::Reconfigurable& design = scene();
    if (action == "expect-count") {
      const std::size_t count = kind->second == "part"    ? design.parts.size()
                                : kind->second == "state" ? design.states.size()
                                                          : design.transitions.size();
      if (static_cast<double>(count) != number(args, 1, "count"))
        fail(fmt::format("expected {} {}, the design has {}", args[1], args[0], count));
      return;
    }
    const int index = kind->second == "part"    ? design.find_part(args[1])
                      : kind->second == "state" ? design.find_state(args[1])
                                                : design.find_transition(args[1]);
    if ((index >= 0) != (action == "expect-name"))
      fail(fmt::format("expected {} {} \"{}\"", action == "expect-name" ? "a" : "no", kind->second, args[1]));
  }

  HeadlessFrontend& frontend_;
  const std::function<void(const std::string&)>& fail_;
};

}  // namespace

bool run_authoring_action(HeadlessFrontend& frontend, const std::string& action, const std::vector<std::string>& args,
                          const std::function<void(const std::string&)>& fail) {
  return AuthoringActions(frontend, fail).run(action, args);
}

}  // namespace reconfig::studio
