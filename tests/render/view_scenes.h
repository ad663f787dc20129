#pragma once
/// @file
/// Small designs for the view selection tests: boxes built in code, each part sliding in a
/// straight line over the one transition "move" (or holding still), and a ray-cast count of
/// the pixels of a box that show (the oracle of the occlusion query).

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/reconfigurable.h"
#include "reconfig/view/picking.h"

namespace reconfig::render::testing {

/// A box of `size` centered at `from` at t = 0 and at `to` at t = 1.
struct SlidingBox {
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  Eigen::Vector3d to = Eigen::Vector3d::Zero();
};

inline scene::Reconfigurable sliding_boxes(const std::vector<SlidingBox>& boxes) {
  scene::Reconfigurable scene;
  scene.states = {{"start", {}}, {"end", {}}};
  scene.transitions.push_back({"move", "start", "end", true, {}});
  for (const SlidingBox& box : boxes) {
    scene::Part part;
    part.name = "box" + std::to_string(scene.parts.size());
    part.source = scene::EditedMesh{};
    part.mesh = geometry::make_box(box.size);
    part.center = scene::part_center(part.mesh);
    part.mesh.V.rowwise() += (box.from - part.center).transpose();
    part.center = box.from;
    scene.parts.push_back(part);
    if (box.to == box.from) continue;
    const Eigen::Vector3d d = box.to - box.from;
    scene::KeyframedTrack track;
    track.translation.push_back({0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), d / 3});
    track.translation.push_back({1.0, d, 2 * d / 3, d});
    scene.states[1].poses[part.name] = {Eigen::Quaterniond::Identity(), d};
    scene.transitions[0].tracks[part.name] = track;
  }
  return scene;
}

/// Ray parameter where `ray` enters `box` (0 when it starts inside), or a negative number.
inline double ray_box_entry(const view::Ray& ray, const Eigen::AlignedBox3d& box) {
  double enter = 0, leave = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (ray.direction[k] == 0) {
      if (ray.origin[k] < box.min()[k] || ray.origin[k] > box.max()[k]) return -1;
      continue;
    }
    double a = (box.min()[k] - ray.origin[k]) / ray.direction[k], b = (box.max()[k] - ray.origin[k]) / ray.direction[k];
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    leave = std::min(leave, b);
  }
  return enter <= leave ? enter : -1;
}

struct RayCount {
  long visible = 0, total = 0;
};

/// The oracle: through the center of every pixel of a `resolution`² image, whether the ray
/// meets `box` and meets no occluder triangle before it (within `slack` times the distance).
inline RayCount ray_cast_count(const view::Camera& camera, int resolution, const Eigen::AlignedBox3d& box,
                               const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, double slack = 1e-4) {
  RayCount count;
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const view::Ray ray = view::ray_from_pixel(camera, resolution, resolution, x + 0.5, y + 0.5);
      const double s = ray_box_entry(ray, box);
      if (s < 0) continue;
      ++count.total;
      const auto hit = view::ray_mesh(ray, V, F);
      if (!hit || s <= hit->s * (1 + slack)) ++count.visible;
    }
  return count;
}

}  // namespace reconfig::render::testing
