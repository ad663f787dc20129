#include "reconfig/scene/edits.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "reconfig/common/input_error.h"
#include "reconfig/motion/screw_track.h"
#include "reconfig/scene/validate_scene.h"

namespace reconfig::scene {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw InputError("", "", message); }

/// Everything about one part that an edit may change, copied so the edit can be undone.
struct PartSlice {
  std::vector<std::optional<motion::Pose>> state_poses;  ///< per state; nullopt = not listed
  std::vector<std::optional<Track>> tracks;              ///< per transition; nullopt = no track
  std::optional<geometry::Mesh> mesh;                    ///< only for geometry edits
  PartSource source;
};

PartSlice capture(const Reconfigurable& scene, int part, bool geometry) {
  const Part& p = scene.parts[part];
  PartSlice slice;
  for (const State& state : scene.states) {
    const auto it = state.poses.find(p.name);
    slice.state_poses.push_back(it == state.poses.end() ? std::nullopt : std::optional(it->second));
  }
  for (const Transition& transition : scene.transitions) {
    const auto it = transition.tracks.find(p.name);
    slice.tracks.push_back(it == transition.tracks.end() ? std::nullopt : std::optional(it->second));
  }
  if (geometry) slice.mesh = p.mesh;
  slice.source = p.source;
  return slice;
}

void restore(Reconfigurable& scene, int part, const PartSlice& slice) {
  Part& p = scene.parts[part];
  for (std::size_t s = 0; s < scene.states.size(); ++s) {
    if (slice.state_poses[s]) scene.states[s].poses[p.name] = *slice.state_poses[s];
    else scene.states[s].poses.erase(p.name);
  }
  for (std::size_t t = 0; t < scene.transitions.size(); ++t) {
    if (slice.tracks[t]) scene.transitions[t].tracks[p.name] = *slice.tracks[t];
    else scene.transitions[t].tracks.erase(p.name);
  }
  if (slice.mesh) p.mesh = *slice.mesh;
  p.source = slice.source;
}

/// A command that edits one part's poses, tracks or geometry. The first `apply` runs the
/// edit, validates the scene and records the part before and after; later applies and reverts
/// restore those copies, so redo gives exactly what the edit gave.
class PartEdit final : public Command {
 public:
  using Mutation = std::function<DirtySet(Reconfigurable&, int part)>;
  PartEdit(std::string label, std::string part, bool geometry, Mutation mutate)
      : label_(std::move(label)), part_name_(std::move(part)), geometry_(geometry), mutate_(std::move(mutate)) {}

  DirtySet apply(Reconfigurable& scene) override {
    const int part = scene.find_part(part_name_);
    if (part < 0) refuse(fmt::format("unknown part \"{}\"", part_name_));
    if (after_) {
      restore(scene, part, *after_);
      return dirty_;
    }
    PartSlice before = capture(scene, part, geometry_);
    try {
      dirty_ = mutate_(scene, part);
      validate_scene(scene);
    } catch (...) {
      restore(scene, part, before);
      throw;
    }
    before_ = std::move(before);
    after_ = capture(scene, part, geometry_);
    return dirty_;
  }

  DirtySet revert(Reconfigurable& scene) override {
    restore(scene, scene.find_part(part_name_), *before_);
    return dirty_;
  }

  std::string label() const override { return label_; }

 private:
  std::string label_, part_name_;
  bool geometry_;
  Mutation mutate_;
  std::optional<PartSlice> before_, after_;
  DirtySet dirty_;
};

int transition_index(const Reconfigurable& scene, const std::string& name) {
  const int index = scene.find_transition(name);
  if (index < 0) refuse(fmt::format("unknown transition \"{}\"", name));
  return index;
}

Track* find_track(Reconfigurable& scene, int transition, const std::string& part) {
  auto& tracks = scene.transitions[transition].tracks;
  const auto it = tracks.find(part);
  return it == tracks.end() ? nullptr : &it->second;
}

KeyframedTrack& keyframed(Reconfigurable& scene, int transition, const std::string& part) {
  Track* track = find_track(scene, transition, part);
  if (!track) refuse(fmt::format("part \"{}\" has no track in this transition", part));
  auto* keyed = std::get_if<KeyframedTrack>(track);
  if (!keyed) refuse(fmt::format("part \"{}\" moves by screw poses here, not by keyframes", part));
  return *keyed;
}

/// The dirty set of a change to the motion of `part` between times t0 and t1.
DirtySet motion_changed(int transition, int part, double t0, double t1) {
  DirtySet dirty;
  dirty.ranges.push_back({transition, part, t0, t1});
  return dirty;
}

/// Checks that an inner key may take `time` and returns the span its change affects.
template <typename Key>
std::pair<double, double> inner_key_span(const std::vector<Key>& keys, int key, double time, const char* kind) {
  const int n = static_cast<int>(keys.size());
  if (key < 0 || key >= n) refuse(fmt::format("no {} key {} (the track has {})", kind, key, n));
  if (key == 0 || key == n - 1)
    refuse(fmt::format("the first and last {} keys follow the state poses: edit the state instead", kind));
  const double lo = keys[key - 1].time, hi = keys[key + 1].time;
  if (!(time > lo && time < hi))
    refuse(fmt::format("key time {} must stay between its neighbours ({}, {})", time, lo, hi));
  return {lo, hi};
}

/// Splits the Bézier segment containing t at t (de Casteljau): the curve keeps its shape.
void insert_translation_key(std::vector<motion::TranslationKey>& keys, double t) {
  const motion::BezierTranslationTrack track(keys);
  std::size_t j = 0;
  while (j + 2 < keys.size() && keys[j + 1].time <= t) ++j;
  const double f = (t - keys[j].time) / (keys[j + 1].time - keys[j].time);
  const Eigen::Vector3d p0 = keys[j].point, p1 = keys[j].out, p2 = keys[j + 1].in, p3 = keys[j + 1].point;
  const Eigen::Vector3d a = p0 + f * (p1 - p0), b = p1 + f * (p2 - p1), c = p2 + f * (p3 - p2);
  const Eigen::Vector3d d = a + f * (b - a), e = b + f * (c - b);
  keys[j].out = a;
  keys[j + 1].in = c;
  keys.insert(keys.begin() + static_cast<std::ptrdiff_t>(j) + 1, motion::TranslationKey{t, track.evaluate(t), d, e});
}

template <typename Key>
void check_insertable(const std::vector<Key>& keys, double t) {
  if (!(t > keys.front().time && t < keys.back().time))
    refuse(fmt::format("a new key must lie strictly between the first and last keys ({}, {})", keys.front().time,
                       keys.back().time));
  for (const Key& key : keys)
    if (key.time == t) refuse(fmt::format("there is already a key at time {}", t));
}

/// A keyframed track for a part that had none: it holds `pose` (its pose in both states).
KeyframedTrack holding_track(const motion::Pose& pose) {
  KeyframedTrack track;
  const Eigen::Vector3d x = pose.translation;
  track.translation = {{0.0, x, x, x}, {1.0, x, x, x}};
  track.rotation = {{0.0, pose.rotation}, {1.0, pose.rotation}};
  return track;
}

}  // namespace

std::unique_ptr<Command> set_translation_key(std::string transition, std::string part, int key,
                                             motion::TranslationKey value) {
  std::string label = fmt::format("move translation key {} of {}", key, part);
  return std::make_unique<PartEdit>(std::move(label), part, false, [=](Reconfigurable& scene, int p) {
    const int tr = transition_index(scene, transition);
    auto& keys = keyframed(scene, tr, part).translation;
    const int last = static_cast<int>(keys.size()) - 1;
    const bool end = key >= 0 && key <= last && (key == 0 || key == last);
    if (end && value.time == keys[key].time && value.point == keys[key].point) {
      // The first and last keys' time and point follow the state poses; their handles do not.
      keys[key].in = value.in;
      keys[key].out = value.out;
      return motion_changed(tr, p, key == 0 ? 0.0 : keys[key - 1].time, key == last ? 1.0 : keys[key + 1].time);
    }
    const auto [lo, hi] = inner_key_span(keys, key, value.time, "translation");
    keys[key] = value;
    return motion_changed(tr, p, lo, hi);
  });
}

std::unique_ptr<Command> set_rotation_key(std::string transition, std::string part, int key, motion::RotationKey value) {
  std::string label = fmt::format("move rotation key {} of {}", key, part);
  return std::make_unique<PartEdit>(std::move(label), part, false,
                                    [=](Reconfigurable& scene, int p) {
                                      const int tr = transition_index(scene, transition);
                                      auto& keys = keyframed(scene, tr, part).rotation;
                                      const auto [lo, hi] = inner_key_span(keys, key, value.time, "rotation");
                                      keys[key] = {value.time, value.rotation.normalized()};
                                      return motion_changed(tr, p, lo, hi);
                                    });
}

std::unique_ptr<Command> insert_key(std::string transition, std::string part, KeyKind kind, double t) {
  std::string label = fmt::format("insert {} key at t = {:.3f} for {}",
                                  kind == KeyKind::kTranslation ? "translation" : "rotation", t, part);
  return std::make_unique<PartEdit>(std::move(label), part, false, [=](Reconfigurable& scene, int p) {
    const int tr = transition_index(scene, transition);
    const motion::Pose hold = scene.pose_at(tr, p, 0.0);
    Track* track = find_track(scene, tr, part);
    if (!track) track = &(scene.transitions[tr].tracks[part] = holding_track(hold));
    if (auto* screw = std::get_if<ScrewPosesTrack>(track)) {
      check_insertable(screw->poses, t);
      const motion::Pose pose = scene.pose_at(tr, p, t);
      const auto at = std::upper_bound(screw->poses.begin(), screw->poses.end(), t,
                                       [](double time, const motion::ScrewKey& k) { return time < k.time; });
      const double lo = std::prev(at)->time, hi = at->time;
      screw->poses.insert(at, motion::ScrewKey{t, pose});
      return motion_changed(tr, p, lo, hi);
    }
    auto& keyed = std::get<KeyframedTrack>(*track);
    if (kind == KeyKind::kTranslation) {
      if (keyed.translation.empty()) keyed.translation = holding_track(hold).translation;
      check_insertable(keyed.translation, t);
      insert_translation_key(keyed.translation, t);
    } else {
      if (keyed.rotation.empty()) keyed.rotation = holding_track(hold).rotation;
      check_insertable(keyed.rotation, t);
      const Eigen::Quaterniond q = motion::SlerpRotationTrack(keyed.rotation).evaluate(t);
      const auto at = std::upper_bound(keyed.rotation.begin(), keyed.rotation.end(), t,
                                       [](double time, const motion::RotationKey& k) { return time < k.time; });
      keyed.rotation.insert(at, motion::RotationKey{t, q});
    }
    const std::vector<double> times = key_times(*track);
    const auto at = std::find(times.begin(), times.end(), t);
    return motion_changed(tr, p, at == times.begin() ? 0.0 : *std::prev(at),
                          std::next(at) == times.end() ? 1.0 : *std::next(at));
  });
}

std::unique_ptr<Command> remove_key(std::string transition, std::string part, KeyKind kind, int key) {
  std::string label =
      fmt::format("remove {} key {} of {}", kind == KeyKind::kTranslation ? "translation" : "rotation", key, part);
  return std::make_unique<PartEdit>(std::move(label), part, false, [=](Reconfigurable& scene, int p) {
    const int tr = transition_index(scene, transition);
    Track* track = find_track(scene, tr, part);
    if (!track) refuse(fmt::format("part \"{}\" has no track in this transition", part));
    const auto remove = [&](auto& keys, const char* name) {
      if (key < 0 || key >= static_cast<int>(keys.size()))
        refuse(fmt::format("no {} key {} (the track has {})", name, key, keys.size()));
      const auto [lo, hi] = inner_key_span(keys, key, keys[key].time, name);
      keys.erase(keys.begin() + key);
      return motion_changed(tr, p, lo, hi);
    };
    if (auto* screw = std::get_if<ScrewPosesTrack>(track)) return remove(screw->poses, "screw");
    auto& keyed = std::get<KeyframedTrack>(*track);
    return kind == KeyKind::kTranslation ? remove(keyed.translation, "translation") : remove(keyed.rotation, "rotation");
  });
}

std::unique_ptr<Command> set_state_pose(std::string state, std::string part, motion::Pose pose) {
  std::string label = fmt::format("set pose of {} in {}", part, state);
  pose.rotation.normalize();
  return std::make_unique<PartEdit>(std::move(label), part, false, [=](Reconfigurable& scene, int p) {
    const int s = scene.find_state(state);
    if (s < 0) refuse(fmt::format("unknown state \"{}\"", state));
    const motion::Pose old = scene.states[s].pose_of(part);
    const Eigen::Vector3d shift = pose.translation - old.translation;
    scene.states[s].poses[part] = pose;
    DirtySet dirty;
    for (int tr = 0; tr < static_cast<int>(scene.transitions.size()); ++tr) {
      const Transition& transition = scene.transitions[tr];
      const bool from = transition.from == state, to = transition.to == state;
      if (!from && !to) continue;
      Track* track = find_track(scene, tr, part);
      if (!track) {  // the part held still; now its two states differ: move it linearly
        const int other = scene.find_state(from ? transition.to : transition.from);
        const motion::Pose a = from ? pose : scene.states[other].pose_of(part);
        const motion::Pose b = to ? pose : scene.states[other].pose_of(part);
        KeyframedTrack moving;
        moving.translation = {{0.0, a.translation, a.translation, a.translation},
                              {1.0, b.translation, b.translation, b.translation}};
        moving.rotation = {{0.0, a.rotation}, {1.0, b.rotation}};
        scene.transitions[tr].tracks[part] = moving;
        dirty.ranges.push_back({tr, p, 0.0, 1.0});
        continue;
      }
      const std::vector<double> times = key_times(*track);
      if (from) dirty.ranges.push_back({tr, p, 0.0, times.size() > 1 ? times[1] : 1.0});
      if (to) dirty.ranges.push_back({tr, p, times.size() > 1 ? times[times.size() - 2] : 0.0, 1.0});
      const auto move_ends = [&](auto&& move) {
        if (from) move(true);
        if (to) move(false);
      };
      if (auto* screw = std::get_if<ScrewPosesTrack>(track)) {
        move_ends([&](bool first) { (first ? screw->poses.front() : screw->poses.back()).pose = pose; });
        continue;
      }
      auto& keyed = std::get<KeyframedTrack>(*track);
      move_ends([&](bool first) {
        if (!keyed.translation.empty()) {
          auto& key = first ? keyed.translation.front() : keyed.translation.back();
          key.point += shift;
          key.in += shift;
          key.out += shift;
        }
        if (!keyed.rotation.empty()) (first ? keyed.rotation.front() : keyed.rotation.back()).rotation = pose.rotation;
      });
      // A component the track does not animate holds the state pose; if the two states now
      // disagree there, the track must animate it.
      const int other = scene.find_state(from ? transition.to : transition.from);
      const motion::Pose a = from ? pose : scene.states[other].pose_of(part);
      const motion::Pose b = to ? pose : scene.states[other].pose_of(part);
      if (keyed.translation.empty() && (a.translation - b.translation).norm() > 0)
        keyed.translation = {{0.0, a.translation, a.translation, a.translation},
                             {1.0, b.translation, b.translation, b.translation}};
      if (keyed.rotation.empty() && a.rotation.angularDistance(b.rotation) > 0)
        keyed.rotation = {{0.0, a.rotation}, {1.0, b.rotation}};
    }
    return dirty;
  });
}

std::unique_ptr<Command> set_pose_at(const Reconfigurable& scene, std::string transition, std::string part, double t,
                                     motion::Pose pose) {
  const int tr = transition_index(scene, transition);
  if (!(t >= 0.0 && t <= 1.0)) refuse(fmt::format("time {} lies outside [0, 1]", t));
  if (t == 0.0) return set_state_pose(scene.transitions[tr].from, std::move(part), pose);
  if (t == 1.0) return set_state_pose(scene.transitions[tr].to, std::move(part), pose);
  std::string label = fmt::format("move {} at t = {:.3f}", part, t);
  pose.rotation.normalize();
  return std::make_unique<PartEdit>(std::move(label), part, false, [=](Reconfigurable& edited, int p) {
    const int index = transition_index(edited, transition);
    Track* track = find_track(edited, index, part);
    if (!track) track = &(edited.transitions[index].tracks[part] = holding_track(edited.pose_at(index, p, 0.0)));
    if (auto* screw = std::get_if<ScrewPosesTrack>(track)) {
      auto at = std::lower_bound(screw->poses.begin(), screw->poses.end(), t,
                                 [](const motion::ScrewKey& k, double time) { return k.time < time; });
      if (at == screw->poses.end() || at->time != t) {
        check_insertable(screw->poses, t);
        at = screw->poses.insert(at, motion::ScrewKey{t, pose});
      }
      at->pose = pose;
      const double lo = at == screw->poses.begin() ? 0.0 : std::prev(at)->time;
      const double hi = std::next(at) == screw->poses.end() ? 1.0 : std::next(at)->time;
      return motion_changed(index, p, lo, hi);
    }
    auto& keyed = std::get<KeyframedTrack>(*track);
    const motion::Pose hold = edited.pose_at(index, p, t);
    if (keyed.translation.empty()) keyed.translation = holding_track(hold).translation;
    if (keyed.rotation.empty()) keyed.rotation = holding_track(hold).rotation;
    const auto key_at = [t](auto& keys) {
      return std::find_if(keys.begin(), keys.end(), [t](const auto& key) { return key.time == t; });
    };
    if (key_at(keyed.translation) == keyed.translation.end()) {
      check_insertable(keyed.translation, t);
      insert_translation_key(keyed.translation, t);
    }
    auto translation = key_at(keyed.translation);
    const Eigen::Vector3d shift = pose.translation - translation->point;
    translation->point += shift;
    translation->in += shift;
    translation->out += shift;
    auto rotation = key_at(keyed.rotation);
    if (rotation == keyed.rotation.end()) {
      check_insertable(keyed.rotation, t);
      rotation = keyed.rotation.insert(
          std::upper_bound(keyed.rotation.begin(), keyed.rotation.end(), t,
                           [](double time, const motion::RotationKey& k) { return time < k.time; }),
          motion::RotationKey{t, pose.rotation});
    }
    rotation->rotation = pose.rotation;
    // Each component changed between its own neighbouring keys.
    const auto span = [t](const auto& keys) {
      const auto at = std::find_if(keys.begin(), keys.end(), [t](const auto& key) { return key.time == t; });
      if (at == keys.begin() || std::next(at) == keys.end())
        refuse("the first and last keys follow the state poses: edit the state instead");
      return std::pair(std::prev(at)->time, std::next(at)->time);
    };
    const auto [t_lo, t_hi] = span(keyed.translation);
    const auto [r_lo, r_hi] = span(keyed.rotation);
    return motion_changed(index, p, std::min(t_lo, r_lo), std::max(t_hi, r_hi));
  });
}

std::unique_ptr<Command> replace_part_mesh(std::string part, geometry::Mesh mesh, PartSource source) {
  std::string label = fmt::format("replace geometry of {}", part);
  return std::make_unique<PartEdit>(std::move(label), part, true,
                                    [mesh = std::move(mesh), source = std::move(source)](Reconfigurable& scene, int p) {
    if (mesh.empty()) refuse("the new geometry has no triangles");
    scene.parts[p].mesh = mesh;
    scene.parts[p].source = source;
    DirtySet dirty;
    dirty.geometry_changed.push_back(p);
    for (int tr = 0; tr < static_cast<int>(scene.transitions.size()); ++tr) dirty.ranges.push_back({tr, p, 0.0, 1.0});
    return dirty;
  });
}

namespace {

class CollisionSettingsEdit final : public Command {
 public:
  explicit CollisionSettingsEdit(CollisionSettings settings) : settings_(std::move(settings)) {}

  DirtySet apply(Reconfigurable& scene) override {
    if (const std::string problem = settings_.problem(); !problem.empty()) refuse(problem);
    before_ = scene.collision;
    scene.collision = settings_;
    return everything();
  }
  DirtySet revert(Reconfigurable& scene) override {
    scene.collision = before_;
    return everything();
  }
  std::string label() const override { return "change collision settings"; }

 private:
  static DirtySet everything() {
    DirtySet dirty;
    dirty.structure_changed = true;
    return dirty;
  }
  CollisionSettings settings_, before_;
};

}  // namespace

std::unique_ptr<Command> set_collision_settings(CollisionSettings settings) {
  return std::make_unique<CollisionSettingsEdit>(std::move(settings));
}

}  // namespace reconfig::scene
