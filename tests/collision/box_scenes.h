#pragma once
/// @file
/// Scenes of unit boxes for the contact semantics and clearance tests: one box sliding along a
/// straight, constant-speed track past boxes that hold still.

#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "reconfig/scene/scene_file.h"

namespace reconfig::collision::test {

inline nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
inline nlohmann::json quat(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

/// A straight, constant-speed Bézier track from a to b (handles at thirds).
inline nlohmann::json linear_track(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {{"translation",
           {{{"time", 0}, {"point", vec(a)}, {"in", vec(a)}, {"out", vec(a + (b - a) / 3)}},
            {{"time", 1}, {"point", vec(b)}, {"in", vec(b - (b - a) / 3)}, {"out", vec(b)}}}}};
}

/// Unit boxes: "mover" slides from `from` to `to`, the others hold still at `fixed`; every
/// position and orientation is turned by `turn` (about the origin). `collision`, if not null,
/// is the scene's "collision" object.
inline scene::Reconfigurable boxes(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   const std::vector<Eigen::Vector3d>& fixed,
                                   const Eigen::Quaterniond& turn = {1, 0, 0, 0}, double mover_size = 1,
                                   const nlohmann::json& collision = nullptr) {
  nlohmann::json parts = {{{"name", "mover"}, {"box", {{"size", {mover_size, mover_size, mover_size}}}}}};
  nlohmann::json start = {{"mover", {{"translation", vec(turn * from)}, {"rotation", quat(turn)}}}};
  nlohmann::json end = {{"mover", {{"translation", vec(turn * to)}, {"rotation", quat(turn)}}}};
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    const std::string name = std::string("fixed").append(std::to_string(i));
    parts.push_back({{"name", name}, {"box", {{"size", {1, 1, 1}}}}});
    start[name] = end[name] = {{"translation", vec(turn * fixed[i])}, {"rotation", quat(turn)}};
  }
  nlohmann::json document = {
      {"format", "reconfig-scene"},
      {"version", 1},
      {"parts", parts},
      {"states", {{{"name", "start"}, {"poses", start}}, {{"name", "end"}, {"poses", end}}}},
      {"transitions",
       {{{"name", "slide"}, {"from", "start"}, {"to", "end"}, {"tracks", {{"mover", linear_track(turn * from, turn * to)}}}}}}};
  if (!collision.is_null()) document["collision"] = collision;
  return scene::parse_scene(document.dump(), std::filesystem::current_path(), "test.json");
}

}  // namespace reconfig::collision::test
