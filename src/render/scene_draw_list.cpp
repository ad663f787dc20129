#include "reconfig/render/scene_draw_list.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "reconfig/geometry/bounding_box.h"


namespace reconfig::render {

Eigen::Vector3f part_color(const scene::Reconfigurable& scene, int part) {
  if (scene.parts[part].color) return scene.parts[part].color->cast<float>();
  static const Eigen::Vector3f kPalette[] = {{0.35f, 0.55f, 0.8f}, {0.85f, 0.55f, 0.25f}, {0.45f, 0.7f, 0.4f},
                                             {0.75f, 0.4f, 0.6f},  {0.55f, 0.5f, 0.75f},  {0.8f, 0.75f, 0.35f}};
  return kPalette[part % 6];
}

double grid_spacing_for(double size) {
  if (!(size > 0) || !std::isfinite(size)) return 1.0;
  const double rough = size / 10;
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  const double mantissa = rough / decade;
  return decade * (mantissa < 1.5 ? 1 : mantissa < 3.5 ? 2 : mantissa < 7.5 ? 5 : 10);
}

namespace {

/// The box of `mesh`'s rest bounding box corners under `placement` (contains the posed mesh).
Eigen::AlignedBox3d placed_box(const geometry::Mesh& mesh, const Eigen::Isometry3d& placement) {
  const Eigen::AlignedBox3d rest = geometry::bounding_box(mesh.V);
  Eigen::AlignedBox3d placed;
  if (rest.isEmpty()) return placed;
  for (int corner = 0; corner < 8; ++corner)
    placed.extend(placement * rest.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)));
  return placed;
}

}  // namespace

DrawList scene_draw_list(const scene::Reconfigurable& scene, const SceneDrawRequest& request) {
  assert(request.transition >= 0 || request.state >= 0);
  DrawList list;
  const int parts = static_cast<int>(scene.parts.size());
  const bool resident = static_cast<int>(request.resident_meshes.size()) == parts;
  auto pose_of = [&](int part, double t) {
    for (const auto& [overridden, pose] : request.pose_overrides)
      if (overridden == part) return pose;
    return request.transition >= 0 ? scene.pose_at(request.transition, part, t)
                                   : scene.states[request.state].pose_of(scene.parts[part].name);
  };
  // One part at one pose, either posed here or left to the GPU.
  auto item_for = [&](int part, const motion::Pose& pose) {
    MeshItem item;
    item.color = part_color(scene, part);
    item.cull_back_faces = static_cast<int>(request.solid_parts.size()) == parts && request.solid_parts[part];
    if (resident) {
      item.rest = request.resident_meshes[part];
      item.placement = pose.to_isometry(scene.parts[part].center);
    } else {
      item.V = scene::posed_part_vertices(scene.parts[part], pose);
      item.F = scene.parts[part].mesh.F;
    }
    return item;
  };
  std::vector<motion::Pose> poses;
  Eigen::AlignedBox3d bounds;
  for (int p = 0; p < parts; ++p) {
    poses.push_back(pose_of(p, request.time));
    MeshItem item = item_for(p, poses.back());
    item.highlighted = std::find(request.selected.begin(), request.selected.end(), p) != request.selected.end();
    bounds.extend(resident ? placed_box(*item.rest, item.placement) : geometry::bounding_box(item.V));
    list.meshes.push_back(std::move(item));
  }
  if (request.transition >= 0) {
    for (const view::GhostSample& ghost : request.ghosts)
      for (int p = 0; p < parts; ++p) {
        const motion::Pose pose = scene.pose_at(request.transition, p, ghost.time);
        // A part that does not move is not ghosted (it would only veil itself).
        if ((pose.translation - poses[p].translation).norm() < 1e-9 &&
            std::abs(std::abs(pose.rotation.dot(poses[p].rotation)) - 1) < 1e-12)
          continue;
        MeshItem item = item_for(p, pose);
        item.opacity = std::clamp(request.ghost_opacity * static_cast<float>(ghost.weight), 0.02f, 0.99f);
        item.cull_back_faces = false;  // a see-through ghost shows its far side
        list.meshes.push_back(std::move(item));
      }
  }
  for (const Eigen::AlignedBox3d& box : request.boxes) list.boxes.push_back({box});

  list.grid.visible = request.grid && !bounds.isEmpty();
  if (list.grid.visible) {
    const double size = bounds.sizes().head<2>().maxCoeff();
    const double spacing = grid_spacing_for(std::max(size, 1e-3));
    list.grid.spacing = spacing;
    list.grid.center = (bounds.center().head<2>() / spacing).array().round().matrix() * spacing;
    list.grid.height = bounds.min().z();
    list.grid.half_lines = static_cast<int>(std::ceil(size / spacing)) + 2;
  }
  return list;
}

}  // namespace reconfig::render
