#include "reconfig/scene/validate_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "reconfig/common/input_error.h"

namespace reconfig::scene {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) { throw InputError("", path, message); }

std::string format_vector(const Eigen::Vector3d& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x(), v.y(), v.z()); }

std::string format_quaternion(const Eigen::Quaterniond& q) {
  return fmt::format("[{:.6g}, {:.6g}, {:.6g}, {:.6g}]", q.w(), q.x(), q.y(), q.z());
}

// The checks below run on every edit, over the whole design: they take the JSON path of what
// they check as a function (`path_of()`), which formats it only if the check fails.

/// Returns the names (for lookups that stay fast with 10,000 parts).
template <typename Named>
std::set<std::string> check_unique_names(const std::vector<Named>& items, const std::string& list) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto path = [&] { return fmt::format("{}[{}].name", list, i); };
    if (items[i].name.empty()) fail(path(), "name must not be empty");
    if (!seen.insert(items[i].name).second) fail(path(), fmt::format("duplicate name \"{}\"", items[i].name));
  }
  return seen;
}

/// Positions must be finite and within `limit` of the origin.
void check_position(const Eigen::Vector3d& v, double limit, const auto& path_of) {
  if (!v.allFinite()) fail(path_of(), "coordinates must be finite numbers");
  if (v.cwiseAbs().maxCoeff() > limit)
    fail(path_of(), fmt::format("coordinate {:.6g} lies beyond {:.6g}: {:g} times the design's size, where precision "
                                "is gone", v.cwiseAbs().maxCoeff(), limit, kMaxCoordinateRatio));
}

/// The largest |coordinate| a position may have: kMaxCoordinateRatio times the design's size.
double position_limit(const Reconfigurable& scene) {
  double size = 0;
  for (const Part& part : scene.parts)
    if (part.mesh.V.size() > 0) size = std::max(size, part.mesh.V.cwiseAbs().maxCoeff());
  return size > 0 ? kMaxCoordinateRatio * size : std::numeric_limits<double>::infinity();
}

void check_unit(const Eigen::Quaterniond& q, const auto& path_of) {
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-3)
    fail(path_of(), fmt::format("quaternion must have unit length, found length {:.6g}", q.norm()));
}

/// Key times must lie in [0, 1] and strictly increase.
template <typename Key>
void check_times(const std::vector<Key>& keys, const auto& list_of) {
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto path = [&] { return fmt::format("{}[{}].time", list_of(), k); };
    const double t = keys[k].time;
    if (!std::isfinite(t) || t < 0 || t > 1) fail(path(), fmt::format("key time {} must lie in [0, 1]", t));
    if (k > 0 && !(t > keys[k - 1].time))
      fail(path(), fmt::format("keyframe times must strictly increase ({} follows {})", t, keys[k - 1].time));
  }
}

std::string mismatch(const char* which, const std::string& what, const std::string& part, const std::string& state,
                     const std::string& expected) {
  return fmt::format("{} key {} does not match the pose of part \"{}\" in state \"{}\" ({})", which, what, part,
                     state, expected);
}

void check_translation_end(const Eigen::Vector3d& point, const motion::Pose& pose, const char* which,
                           const auto& path_of, const std::string& part, const std::string& state,
                           const PoseTolerance& tolerance) {
  if ((point - pose.translation).norm() > tolerance.translation)
    fail(path_of(), mismatch(which, format_vector(point), part, state, format_vector(pose.translation)));
}

void check_rotation_end(const Eigen::Quaterniond& q, const motion::Pose& pose, const char* which,
                        const auto& path_of, const std::string& part, const std::string& state,
                        const PoseTolerance& tolerance) {
  if (q.angularDistance(pose.rotation) > tolerance.rotation)
    fail(path_of(), mismatch(which, format_quaternion(q), part, state, format_quaternion(pose.rotation)));
}

/// `path_of()`: the track's JSON path.
void check_track(const Track& track, const auto& path_of, const std::string& part, const State& from,
                 const State& to, const PoseTolerance& tolerance, double limit) {
  const motion::Pose first = from.pose_of(part);
  const motion::Pose last = to.pose_of(part);
  if (const auto* screw = std::get_if<ScrewPosesTrack>(&track)) {
    const auto list = [&] { return path_of() + ".poses"; };
    if (screw->poses.empty()) fail(list(), "a screw track needs at least one key pose");
    check_times(screw->poses, list);
    for (std::size_t k = 0; k < screw->poses.size(); ++k) {
      check_position(screw->poses[k].pose.translation, limit, [&] { return fmt::format("{}[{}].translation", list(), k); });
      check_unit(screw->poses[k].pose.rotation, [&] { return fmt::format("{}[{}].rotation", list(), k); });
    }
    const std::size_t n = screw->poses.size() - 1;
    for (const auto& [key, pose, state, which] :
         {std::tuple{std::size_t{0}, first, &from, "first"}, std::tuple{n, last, &to, "last"}}) {
      const motion::Pose& p = screw->poses[key].pose;
      const auto at = [&](const char* field) { return fmt::format("{}[{}].{}", list(), key, field); };
      check_translation_end(p.translation, pose, which, [&] { return at("translation"); }, part, state->name, tolerance);
      check_rotation_end(p.rotation, pose, which, [&] { return at("rotation"); }, part, state->name, tolerance);
    }
    return;
  }
  const auto& keyed = std::get<KeyframedTrack>(track);
  const auto translation = [&] { return path_of() + ".translation"; };
  const auto rotation = [&] { return path_of() + ".rotation"; };
  check_times(keyed.translation, translation);
  check_times(keyed.rotation, rotation);
  for (std::size_t k = 0; k < keyed.translation.size(); ++k) {
    const auto& key = keyed.translation[k];
    for (const auto& [v, field] : {std::pair{key.point, "point"}, std::pair{key.in, "in"}, std::pair{key.out, "out"}})
      check_position(v, limit, [&] { return fmt::format("{}[{}].{}", translation(), k, field); });
  }
  for (std::size_t k = 0; k < keyed.rotation.size(); ++k)
    check_unit(keyed.rotation[k].rotation, [&] { return fmt::format("{}[{}].quaternion", rotation(), k); });

  if (keyed.translation.empty()) {
    if ((first.translation - last.translation).norm() > tolerance.translation)
      fail(path_of(), fmt::format("part \"{}\" has no translation keys but its position differs between states \"{}\" "
                                  "and \"{}\"", part, from.name, to.name));
  } else {
    const std::size_t n = keyed.translation.size() - 1;
    check_translation_end(keyed.translation.front().point, first, "first", [&] { return translation() + "[0].point"; },
                          part, from.name, tolerance);
    check_translation_end(keyed.translation.back().point, last, "last",
                          [&] { return fmt::format("{}[{}].point", translation(), n); }, part, to.name, tolerance);
  }
  if (keyed.rotation.empty()) {
    if (first.rotation.angularDistance(last.rotation) > tolerance.rotation)
      fail(path_of(), fmt::format("part \"{}\" has no rotation keys but its rotation differs between states \"{}\" "
                                  "and \"{}\"", part, from.name, to.name));
  } else {
    const std::size_t n = keyed.rotation.size() - 1;
    // The key, not its field: it may be written as `quaternion` or as `rotation` (axis and angle).
    check_rotation_end(keyed.rotation.front().rotation, first, "first", [&] { return rotation() + "[0]"; }, part,
                       from.name, tolerance);
    check_rotation_end(keyed.rotation.back().rotation, last, "last", [&] { return fmt::format("{}[{}]", rotation(), n); },
                       part, to.name, tolerance);
  }
}

}  // namespace

bool poses_match(const motion::Pose& a, const motion::Pose& b, const PoseTolerance& tolerance) {
  return (a.translation - b.translation).norm() <= tolerance.translation &&
         a.rotation.angularDistance(b.rotation) <= tolerance.rotation;
}

void validate_scene(const Reconfigurable& scene, const PoseTolerance& tolerance) {
  if (scene.units.empty()) fail("units", "units must not be empty");
  if (const std::string problem = scene.collision.problem(); !problem.empty()) fail("collision", problem);
  const std::set<std::string> parts = check_unique_names(scene.parts, "parts");
  check_unique_names(scene.states, "states");
  check_unique_names(scene.transitions, "transitions");
  const double limit = position_limit(scene);
  for (std::size_t i = 0; i < scene.parts.size(); ++i) {
    const Part& part = scene.parts[i];
    if (part.mesh.empty()) fail(fmt::format("parts[{}]", i), fmt::format("part \"{}\" has no triangles", part.name));
    check_position(part.center, limit, [&] { return fmt::format("parts[{}].center", i); });
  }
  if (scene.states.empty() && !scene.transitions.empty()) fail("states", "transitions need states");
  for (std::size_t i = 0; i < scene.states.size(); ++i) {
    for (const auto& [name, pose] : scene.states[i].poses) {
      const auto path = [&] { return fmt::format("states[{}].poses.{}", i, name); };
      if (!parts.contains(name)) fail(path(), fmt::format("unknown part \"{}\"", name));
      check_position(pose.translation, limit, [&] { return path() + ".translation"; });
      check_unit(pose.rotation, [&] { return path() + ".rotation"; });
    }
  }
  for (std::size_t i = 0; i < scene.transitions.size(); ++i) {
    const Transition& transition = scene.transitions[i];
    const auto path_of = [&] { return fmt::format("transitions[{}]", i); };
    const int from = scene.find_state(transition.from);
    const int to = scene.find_state(transition.to);
    if (from < 0) fail(path_of() + ".from", fmt::format("unknown state \"{}\"", transition.from));
    if (to < 0) fail(path_of() + ".to", fmt::format("unknown state \"{}\"", transition.to));
    if (transition.linkage) {
      for (std::size_t k = 0; k < transition.linkage->attach.size(); ++k) {
        const std::string& name = transition.linkage->attach[k].part;
        if (!parts.contains(name))
          fail(fmt::format("{}.linkage.attach[{}].part", path_of(), k), fmt::format("unknown part \"{}\"", name));
      }
      if (const std::string part = edited_driven_part(transition); !part.empty())
        fail(fmt::format("{}.tracks.{}", path_of(), part),
             fmt::format("part \"{}\" is driven by the linkage of transition \"{}\": edit the drive (and compile "
                         "it again), not the part's track", part, transition.name));
    }
    for (const auto& [name, track] : transition.tracks)
      if (!parts.contains(name))
        fail(fmt::format("{}.tracks.{}", path_of(), name), fmt::format("unknown part \"{}\"", name));
    for (const Part& part : scene.parts) {
      const auto track = transition.tracks.find(part.name);
      if (track != transition.tracks.end()) {
        check_track(track->second, [&] { return fmt::format("{}.tracks.{}", path_of(), part.name); }, part.name,
                    scene.states[from], scene.states[to], tolerance, limit);
      } else if (!poses_match(scene.states[from].pose_of(part.name), scene.states[to].pose_of(part.name), tolerance)) {
        fail(path_of() + ".tracks", fmt::format("part \"{}\" has no track but its pose differs between states \"{}\" and "
                                           "\"{}\"", part.name, transition.from, transition.to));
      }
    }
  }
}

}  // namespace reconfig::scene
