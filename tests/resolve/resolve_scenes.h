#pragma once
/// @file
/// Small designs for the resolve tests: parts built in code, one transition "move".

#include <Eigen/Geometry>

#include <algorithm>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve::testing {

/// A closed prism: the polygon `outline` (x, z), star-shaped from its first corner, extruded
/// over y ∈ [−depth/2, depth/2]; faces oriented outward.
inline geometry::Mesh extruded(const std::vector<Eigen::Vector2d>& outline, double depth) {
  const int n = static_cast<int>(outline.size());
  geometry::Mesh mesh;
  mesh.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    mesh.V.row(i) << outline[i].x(), -depth / 2, outline[i].y();
    mesh.V.row(n + i) << outline[i].x(), depth / 2, outline[i].y();
  }
  std::vector<Eigen::Vector3i> faces;
  for (int i = 1; i + 1 < n; ++i) {
    faces.emplace_back(0, i, i + 1);          // front cap (y = −depth/2)
    faces.emplace_back(n, n + i + 1, n + i);  // back cap
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    faces.emplace_back(i, n + i, j);
    faces.emplace_back(j, n + i, n + j);
  }
  mesh.F.resize(static_cast<int>(faces.size()), 3);
  double volume = 0;  // divergence theorem: positive when the faces point outward
  for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
    mesh.F.row(f) = faces[f].transpose();
    volume += Eigen::Vector3d(mesh.V.row(faces[f][0])).dot(Eigen::Vector3d(mesh.V.row(faces[f][1])).cross(Eigen::Vector3d(mesh.V.row(faces[f][2]))));
  }
  if (volume < 0) mesh.F.col(1).swap(mesh.F.col(2));
  return mesh;
}

inline scene::Part make_part(std::string name, geometry::Mesh mesh) {
  scene::Part part;
  part.name = std::move(name);
  part.source = scene::EditedMesh{};
  part.mesh = std::move(mesh);
  part.center = scene::part_center(part.mesh);
  return part;
}

/// `transition` run backwards, named `name`: from its end state to its start, every keyframed
/// track reversed in time (handles swapped).
inline scene::Transition reversed_transition(scene::Transition transition, std::string name) {
  transition.name = std::move(name);
  std::swap(transition.from, transition.to);
  for (auto& [part, track] : transition.tracks) {
    auto& keyed = std::get<scene::KeyframedTrack>(track);
    std::reverse(keyed.translation.begin(), keyed.translation.end());
    for (auto& key : keyed.translation) {
      key.time = 1 - key.time;
      std::swap(key.in, key.out);
    }
    std::reverse(keyed.rotation.begin(), keyed.rotation.end());
    for (auto& key : keyed.rotation) key.time = 1 - key.time;
  }
  return transition;
}

/// A design whose part 0 (`still`) holds still and whose part 1 (`mover`) translates along a
/// Bézier track through `points` at evenly spaced times (handles at thirds of the straight
/// segments, so the path is a polyline with eased corners), optionally turning.
inline scene::Reconfigurable two_part_scene(geometry::Mesh still, geometry::Mesh mover,
                                            const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<Eigen::Quaterniond>& rotations = {}) {
  scene::Reconfigurable scene;
  scene.parts = {make_part("still", std::move(still)), make_part("mover", std::move(mover))};
  scene::KeyframedTrack track;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d before = i > 0 ? points[i - 1] : points[i];
    const Eigen::Vector3d after = i + 1 < n ? points[i + 1] : points[i];
    track.translation.push_back({double(i) / (n - 1), points[i], points[i] + (before - points[i]) / 3,
                                 points[i] + (after - points[i]) / 3});
  }
  const int m = static_cast<int>(rotations.size());
  for (int i = 0; i < m; ++i) track.rotation.push_back({double(i) / (m - 1), rotations[i]});
  const Eigen::Quaterniond q0 = m > 0 ? rotations.front() : Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond q1 = m > 0 ? rotations.back() : Eigen::Quaterniond::Identity();
  scene.states = {{"start", {{"mover", {q0, points.front()}}}}, {"end", {{"mover", {q1, points.back()}}}}};
  scene.transitions.push_back({"move", "start", "end", true, {{"mover", track}}});
  return scene;
}

/// The hooks of the paper's Fig. 15 (in the xz plane): a still hook whose tip points up at
/// x ∈ [1.7, 2], z ≤ 0.6, and a narrower hook whose tip hangs down to z = 0.4, sliding along
/// x from −1 to 3 so that the tips cross. Lifting the slider by 0.2 clears them; moving it
/// along x cannot.
inline scene::Reconfigurable hook_scene() {
  const geometry::Mesh still = extruded({{1.7, 0.3}, {0, 0.3}, {0, 0}, {2, 0}, {2, 0.6}, {1.7, 0.6}}, 1.0);
  const geometry::Mesh hook = extruded({{0.3, 0.7}, {2, 0.7}, {2, 1.0}, {0, 1.0}, {0, 0.4}, {0.3, 0.4}}, 0.6);
  return two_part_scene(still, hook, {{-1, 0, 0}, {1, 0, 0}, {3, 0, 0}});
}

/// A small box that passes straight through a big solid box (wholly inside it midway).
inline scene::Reconfigurable box_through_box_scene() {
  return two_part_scene(geometry::make_box({2, 2, 2}), geometry::make_box({0.4, 0.4, 0.4}),
                        {{-3, 0, 0}, {0, 0, 0}, {3, 0, 0}});
}

}  // namespace reconfig::resolve::testing
