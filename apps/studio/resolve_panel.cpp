#include "resolve_panel.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <variant>

#include "reconfig/geometry/bounding_box.h"
#include "studio.h"

namespace reconfig::studio {
namespace {

/// The intervals of `transition` in the snapshot that involve `part`.
std::vector<collision::CollisionInterval> intervals_of(const collision::CollisionSnapshot& snapshot, int transition,
                                                       int part) {
  std::vector<collision::CollisionInterval> found;
  for (const auto& tr : snapshot.transitions)
    if (tr.transition == transition)
      for (const auto& ci : tr.intervals)
        if (std::find(ci.parts.begin(), ci.parts.end(), part) != ci.parts.end()) found.push_back(ci);
  return found;
}

std::string hint_name(const resolve::Hint& hint) {
  if (hint.dof.kind == resolve::DofKind::kTime)
    return fmt::format("time of {} key {}", hint.dof.track == scene::KeyKind::kTranslation ? "translation" : "rotation",
                       hint.dof.key);
  return fmt::format("{} of key {}", resolve::dof_kind_name(hint.dof.kind), hint.dof.key);
}

/// How far the slider reaches each way: half the part's size for points and handles, a
/// quarter turn for rotations, a tenth of the transition for times.
double slide_reach(const resolve::Hint& hint, const geometry::Mesh& mesh) {
  if (hint.dof.kind == resolve::DofKind::kRotation) return M_PI / 2;
  if (hint.dof.kind == resolve::DofKind::kTime) return 0.1;
  return 0.5 * geometry::bounding_box(mesh.V).diagonal().norm();
}

/// The edits that turn `now` into `resolved` (automatic resolution of `transition`): the parts
/// moved in a state (every transition through it follows), then the transition's changed
/// tracks.
std::vector<std::unique_ptr<scene::Command>> resolution_edits(const scene::Reconfigurable& now,
                                                              const scene::Reconfigurable& resolved, int transition) {
  std::vector<std::unique_ptr<scene::Command>> steps;
  for (std::size_t s = 0; s < resolved.states.size(); ++s)
    for (const scene::Part& part : resolved.parts) {
      const motion::Pose was = now.states[s].pose_of(part.name), pose = resolved.states[s].pose_of(part.name);
      if (was != pose)
        steps.push_back(scene::set_state_pose(resolved.states[s].name, part.name, pose));
    }
  std::map<std::string, scene::Track> tracks;
  const auto& before = now.transitions[transition].tracks;
  for (const auto& [part, track] : resolved.transitions[transition].tracks) {
    const auto it = before.find(part);
    if (it == before.end() || track != it->second) tracks[part] = track;
  }
  const std::string& name = resolved.transitions[transition].name;
  if (!tracks.empty()) steps.push_back(scene::set_transition_tracks(name, std::move(tracks), "resolve " + name));
  return steps;
}

}  // namespace

namespace {

/// The hint for `part` over `intervals` of `transition` of `scene` (version `version`).
HintView compute_hint(const scene::Reconfigurable& scene, resolve::ShapeCache& shapes, int transition, int part,
                              std::uint64_t version, const std::vector<collision::CollisionInterval>& intervals) {
  HintView view;
  view.transition = transition;
  view.part = part;
  view.version = version;
  view.result = resolve::compute_hints(scene, shapes, {.transition = transition, .part = part, .intervals = intervals});
  for (int i = 0; i < static_cast<int>(view.result.hints.size()); ++i)
    if (view.result.hints[i].slope < 0 &&
        (view.steepest < 0 || view.result.hints[i].slope < view.result.hints[view.steepest].slope))
      view.steepest = i;
  if (const scene::KeyframedTrack* keyed = scene.keyframed_track(transition, part)) view.base = *keyed;
  return view;
}

/// Triangles of the part and of every part it collides with in `intervals`.
int hinted_triangles(const scene::Reconfigurable& scene, int part,
                     const std::vector<collision::CollisionInterval>& intervals) {
  std::set<int> parts{part};
  for (const auto& ci : intervals) parts.insert(ci.parts.begin(), ci.parts.end());
  int triangles = 0;
  for (int p : parts) triangles += scene.parts[p].mesh.face_count();
  return triangles;
}

}  // namespace

bool ResolvePanel::request_hint(Studio& studio) {
  const int transition = studio.active_transition(), part = studio.selected_part();
  if (!studio.document() || transition < 0 || part < 0) {
    studio.set_status("hint: select a part in an open transition first", true);
    return false;
  }
  if (hint_job_) {
    studio.set_status("hint: still computing the last one");
    return false;
  }
  const Document& document = *studio.document();
  const auto snapshot = studio.collisions();
  const std::vector<collision::CollisionInterval> intervals =
      snapshot ? intervals_of(*snapshot, transition, part) : std::vector<collision::CollisionInterval>{};
  const scene::Reconfigurable& scene = document.scene();
  if (intervals.empty()) {
    studio.set_status(fmt::format("hint: {} does not collide in this transition", scene.parts[part].name));
    hint_.reset();
    return false;
  }
  if (hint_shape_meshes_ != document.part_meshes()) {  // the geometry changed: new shapes
    hint_shapes_ = resolve::ShapeCache();
    hint_shape_meshes_ = document.part_meshes();
  }
  if (hinted_triangles(scene, part, intervals) > studio.options().background_hint_triangles) {
    hint_job_ = std::make_unique<std::future<HintView>>(
        std::async(std::launch::async, [this, design = document.shared_scene(), transition, part,
                                        version = document.version(), intervals] {
          return compute_hint(*design, hint_shapes_, transition, part, version, intervals);
        }));
    studio.set_status(fmt::format("hint: computing for {}...", scene.parts[part].name));
    return true;
  }
  show_hint(studio, compute_hint(scene, hint_shapes_, transition, part, document.version(), intervals));
  return hint_->steepest >= 0;
}

void ResolvePanel::poll_hint(Studio& studio) {
  if (!hint_job_ || hint_job_->wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  HintView view = hint_job_->get();
  hint_job_.reset();
  if (!studio.document() || view.version != studio.document()->version()) {
    studio.set_status("hint dropped: the design changed while it was computed (press H again)");
    return;
  }
  show_hint(studio, std::move(view));
}

void ResolvePanel::show_hint(Studio& studio, HintView view) {
  const std::string& part = studio.document()->scene().parts[view.part].name;
  if (view.steepest < 0) {
    studio.set_status(fmt::format("hint: {} has no keys to move here (energy {:.3g})", part, view.result.energy));
  } else {
    studio.set_status(fmt::format("hint: move the {} (energy {:.3g}, most severe at t = {:.3f})",
                                  hint_name(view.result.hints[view.steepest]), view.result.energy,
                                  view.result.severity_time));
  }
  hint_ = std::move(view);
}

bool ResolvePanel::slide_along_hint(Studio& studio, double amount, bool live) {
  if (!hint_is_current(studio) || hint_->steepest < 0) {
    studio.set_status("slide: no hint for the design as it is (press H)", true);
    return false;
  }
  HintView& view = *hint_;
  const resolve::Hint& hint = view.result.hints[view.steepest];
  const scene::Reconfigurable& scene = studio.document()->scene();
  const std::string& transition = scene.transitions[view.transition].name;
  const std::string& part = scene.parts[view.part].name;
  std::unique_ptr<scene::Command> command;
  const Eigen::VectorXd step = amount * hint.direction;
  if (hint.dof.track == scene::KeyKind::kTranslation) {
    motion::TranslationKey key = view.base.translation.at(hint.dof.key);
    const Eigen::Vector3d d = step.size() == 3 ? Eigen::Vector3d(step) : Eigen::Vector3d::Zero();
    if (hint.dof.kind == resolve::DofKind::kTime) key.time += step[0];
    if (hint.dof.kind == resolve::DofKind::kTranslation || hint.dof.kind == resolve::DofKind::kHandleIn) key.in += d;
    if (hint.dof.kind == resolve::DofKind::kTranslation) key.point += d;
    if (hint.dof.kind == resolve::DofKind::kTranslation || hint.dof.kind == resolve::DofKind::kHandleOut) key.out += d;
    command = scene::set_translation_key(transition, part, hint.dof.key, key);
  } else {
    motion::RotationKey key = view.base.rotation.at(hint.dof.key);
    if (hint.dof.kind == resolve::DofKind::kTime) {
      key.time += step[0];
    } else if (step.norm() > 0) {
      key.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(step.norm(), Eigen::Vector3d(step).normalized())) * key.rotation;
    }
    command = scene::set_rotation_key(transition, part, hint.dof.key, key);
  }
  // The previous position of this slide, if its edit is still the latest.
  if (view.sliding && studio.document()->version() == view.version) studio.document()->undo();
  view.sliding = false;
  const bool applied = studio.execute(std::move(command));
  view.sliding = applied && live;
  view.slide = amount;
  view.version = studio.document()->version();
  return applied;
}

bool ResolvePanel::start_auto_resolve(Studio& studio, bool move_times, bool move_states) {
  const int transition = studio.active_transition();
  if (!studio.document() || transition < 0 || auto_resolve_) return false;
  const Document& document = *studio.document();
  auto job = std::make_unique<AutoResolveJob>();
  job->transition = transition;
  job->version = document.version();
  AutoResolveJob* state = job.get();
  resolve::AutoResolveRequest request;
  request.transition = transition;
  request.detector = document.detector_options();
  request.move_times = move_times;
  request.move_states = move_states;
  request.progress = [state](double fraction) {
    state->progress = fraction;
    return !state->cancel.load();
  };
  request.on_round = [state](const resolve::ResolveRound& round) {
    state->rounds = round.round + 1;
    state->energy = round.energy_after;
  };
  job->result = std::async(std::launch::async, [scene = document.scene(), request] {
    return resolve::auto_resolve(scene, request);
  });
  auto_resolve_ = std::move(job);
  studio.set_status(fmt::format("resolving {} automatically...", document.scene().transitions[transition].name));
  return true;
}

void ResolvePanel::cancel_auto_resolve(Studio& studio) {
  if (!auto_resolve_) return;
  auto_resolve_->cancel = true;
  auto_resolve_->result.wait();
  auto_resolve_.reset();
  studio.set_status("automatic resolution cancelled: nothing changed");
}

void ResolvePanel::poll_auto_resolve(Studio& studio) {
  if (!auto_resolve_ || auto_resolve_->result.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
  const int transition = auto_resolve_->transition;
  const std::uint64_t version = auto_resolve_->version;
  resolve::AutoResolveResult result = auto_resolve_->result.get();
  auto_resolve_.reset();
  const Document* document = studio.document();
  if (!document || result.cancelled) return;
  if (document->version() != version) {  // edits made meanwhile would be overwritten
    studio.set_status("automatic resolution dropped: the design changed while it ran (run it again)", true);
    return;
  }
  const std::string& name = document->scene().transitions[transition].name;
  std::vector<std::unique_ptr<scene::Command>> steps = resolution_edits(document->scene(), result.scene, transition);
  if (steps.empty()) {
    studio.set_status(fmt::format("automatic resolution of {}: {}; nothing changed", name, result.stopped_because),
                      !result.collision_free);
    return;
  }
  std::string elsewhere;
  for (const auto& [other, intervals] : result.rechecked)
    if (intervals > 0) elsewhere += fmt::format("; {} now has {} collision interval(s)", other, intervals);
  const std::string label = fmt::format("resolve {} automatically", name);
  if (studio.execute(scene::command_sequence(label, std::move(steps))))
    studio.set_status(fmt::format("resolved {} automatically in {} rounds: {}{}", name, result.rounds.size(),
                                  result.stopped_because, elsewhere),
                      !result.collision_free || !elsewhere.empty());
  hint_.reset();
}

namespace {

constexpr float kSteepestHint[3] = {1.0f, 0.82f, 0.0f};
constexpr float kOtherHint[3] = {0.95f, 0.9f, 0.45f};

Eigen::Vector3f hint_color(bool steepest) {
  const float* c = steepest ? kSteepestHint : kOtherHint;
  return {c[0], c[1], c[2]};
}

/// A quarter-turn arc about `axis` through `pivot` of radius r, drawn as a polyline ending in an
/// arrow head: how a rotation key should turn.
void add_turn_arc(render::DrawList& list, const Eigen::Vector3d& pivot, const Eigen::Vector3d& axis, double r,
                  const Eigen::Vector3f& color) {
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  render::LineItem arc;
  arc.color = {color.x(), color.y(), color.z(), 1.0f};
  constexpr int kSegments = 24;
  for (int i = 0; i <= kSegments; ++i) {
    const double a = 0.5 * M_PI * i / kSegments;
    arc.points.push_back(pivot + r * (std::cos(a) * u + std::sin(a) * v));
  }
  render::ArrowItem head;  // along the arc's tangent at its end (a = π/2: −u)
  head.from = arc.points.back();
  head.to = arc.points.back() - 0.25 * r * u;
  head.color = color;
  head.head_fraction = 0.9;
  list.lines.push_back(std::move(arc));
  list.arrows.push_back(head);
}

}  // namespace

bool ResolvePanel::hint_is_current(const Studio& studio) const {
  const Document* document = studio.document();
  return document && hint_ && hint_->transition == studio.active_transition() && hint_->version == document->version();
}

void ResolvePanel::add_hint_arrows(const Studio& studio, render::DrawList& list) const {
  if (!hint_is_current(studio)) return;  // after another edit the arrows would point from old places
  const scene::Reconfigurable& scene = studio.document()->scene();
  const scene::Part& part = scene.parts[hint_->part];
  const double length = 0.35 * geometry::bounding_box(part.mesh.V).diagonal().norm();
  const scene::KeyframedTrack* track = scene.keyframed_track(hint_->transition, hint_->part);
  if (!track) return;
  for (int i = 0; i < static_cast<int>(hint_->result.hints.size()); ++i) {
    const resolve::Hint& hint = hint_->result.hints[i];
    if (hint.dof.kind == resolve::DofKind::kTime || hint.slope >= 0) continue;
    const bool steepest = i == hint_->steepest;
    if (hint.dof.kind == resolve::DofKind::kRotation) {
      if (hint.dof.key >= static_cast<int>(track->rotation.size())) continue;
      const double t = track->rotation[hint.dof.key].time;
      const Eigen::Vector3d pivot = scene.pose_at(hint_->transition, hint_->part, t).apply(part.center, part.center);
      add_turn_arc(list, pivot, Eigen::Vector3d(hint.direction), (steepest ? 1.0 : 0.6) * length, hint_color(steepest));
      continue;
    }
    if (hint.dof.key >= static_cast<int>(track->translation.size())) continue;
    const motion::TranslationKey& key = track->translation[hint.dof.key];
    const Eigen::Vector3d at = part.center + (hint.dof.kind == resolve::DofKind::kHandleIn    ? key.in
                                              : hint.dof.kind == resolve::DofKind::kHandleOut ? key.out
                                                                                              : key.point);
    render::ArrowItem arrow;
    arrow.from = at;
    arrow.to = at + (steepest ? 1.0 : 0.5) * length * Eigen::Vector3d(hint.direction);
    arrow.color = hint_color(steepest);
    arrow.head_fraction = 0.3;
    list.arrows.push_back(arrow);
  }
}

void ResolvePanel::draw_timeline_hints(ImDrawList* draw, const Studio& studio) const {
  if (!hint_is_current(studio)) return;
  for (int i = 0; i < static_cast<int>(hint_->result.hints.size()); ++i) {
    const resolve::Hint& hint = hint_->result.hints[i];
    if (hint.dof.kind != resolve::DofKind::kTime || hint.slope >= 0) continue;
    const bool translation = hint.dof.track == scene::KeyKind::kTranslation;
    const std::size_t keys = translation ? hint_->base.translation.size() : hint_->base.rotation.size();
    if (hint.dof.key >= static_cast<int>(keys)) continue;
    const double t = translation ? hint_->base.translation[hint.dof.key].time : hint_->base.rotation[hint.dof.key].time;
    const Layout& layout = studio.layout();
    const float x = studio.timeline_point(t).x, y = translation ? layout.translation_row_y : layout.rotation_row_y;
    const float side = hint.direction[0] > 0 ? 1.0f : -1.0f;  // later or earlier
    const ImU32 color = i == hint_->steepest ? IM_COL32(255, 210, 0, 255) : IM_COL32(240, 228, 115, 255);
    draw->AddTriangleFilled({x + side * 9, y - 6}, {x + side * 9, y + 6}, {x + side * 19, y}, color);
    draw->AddLine({x + side * 3, y}, {x + side * 10, y}, color, 3);
  }
}

void ResolvePanel::forget_hint() {
  if (hint_job_) hint_job_->wait();
  hint_job_.reset();
  hint_.reset();
}

void ResolvePanel::reset() {
  forget_hint();
  if (auto_resolve_) auto_resolve_->cancel = true;
  auto_resolve_.reset();
}

void ResolvePanel::update(Studio& studio) {
  poll_auto_resolve(studio);
  poll_hint(studio);
}

void ResolvePanel::draw(Studio& studio) {
  if (!studio.document() || studio.active_transition() < 0) return;
  ImGui::Separator();
  if (ImGui::Button("Hint (H)")) request_hint(studio);
  ImGui::SameLine();
  draw_auto_resolve(studio);
  if (!hint_ || hint_->transition != studio.active_transition()) return;
  if (!hint_is_current(studio)) {
    ImGui::TextDisabled("the design changed: press H for a new hint");
    return;
  }
  const scene::Reconfigurable& scene = studio.document()->scene();
  ImGui::Text("hint for %s: energy %.3g", scene.parts[hint_->part].name.c_str(), hint_->result.energy);
  if (hint_->steepest >= 0) draw_slider(studio);
}

void ResolvePanel::draw_auto_resolve(Studio& studio) {
  if (auto_resolve_) {
    ImGui::Text("resolving: round %d (energy %.3g), %.0f %%", auto_resolve_->rounds.load(), auto_resolve_->energy.load(),
                100 * auto_resolve_->progress.load());
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) cancel_auto_resolve(studio);
  } else {
    if (ImGui::Button("Resolve automatically")) start_auto_resolve(studio, true, auto_resolve_moves_states_);
    ImGui::SameLine();
    ImGui::Checkbox("states may move", &auto_resolve_moves_states_);
  }
}

void ResolvePanel::draw_slider(Studio& studio) {
  const scene::Reconfigurable& scene = studio.document()->scene();
  const resolve::Hint& hint = hint_->result.hints[hint_->steepest];
  const float reach = static_cast<float>(slide_reach(hint, scene.parts[hint_->part].mesh));
  float slide = static_cast<float>(hint_->slide);
  ImGui::TextWrapped("slide the %s along its hint (yellow arrow):", hint_name(hint).c_str());
  ImGui::SliderFloat("##along the hint", &slide, -reach, reach, "%.3f");
  const bool changed = ImGui::IsItemEdited(), released = ImGui::IsItemDeactivatedAfterEdit();
  if (changed || released) slide_along_hint(studio, slide, !released);
  ImGui::TextDisabled("release: one undoable edit");
}

}  // namespace reconfig::studio
