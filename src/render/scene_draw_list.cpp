#include "reconfig/render/scene_draw_list.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "reconfig/view/scene_bounds.h"

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

DrawList scene_draw_list(const scene::Reconfigurable& scene, const SceneDrawRequest& request) {
  assert(request.transition >= 0 || request.state >= 0);
  DrawList list;
  const int parts = static_cast<int>(scene.parts.size());
  auto posed = [&](int part, double t) -> Eigen::MatrixX3d {
    for (const auto& [overridden, pose] : request.pose_overrides)
      if (overridden == part) return scene::posed_part_vertices(scene.parts[part], pose);
    return request.transition >= 0 ? scene.posed_vertices(request.transition, part, t)
                                   : scene.posed_vertices_in_state(request.state, part);
  };
  for (int p = 0; p < parts; ++p) {
    MeshItem item;
    item.V = posed(p, request.time);
    item.F = scene.parts[p].mesh.F;
    item.color = part_color(scene, p);
    item.highlighted = std::find(request.selected.begin(), request.selected.end(), p) != request.selected.end();
    list.meshes.push_back(std::move(item));
  }
  if (request.transition >= 0) {
    for (const view::GhostSample& ghost : request.ghosts)
      for (int p = 0; p < parts; ++p) {
        MeshItem item;
        item.V = scene.posed_vertices(request.transition, p, ghost.time);
        // A part that does not move is not ghosted (it would only veil itself).
        if ((item.V - list.meshes[p].V).cwiseAbs().maxCoeff() < 1e-9) continue;
        item.F = scene.parts[p].mesh.F;
        item.color = part_color(scene, p);
        item.opacity = std::clamp(request.ghost_opacity * static_cast<float>(ghost.weight), 0.02f, 0.99f);
        list.meshes.push_back(std::move(item));
      }
  }
  for (const Eigen::AlignedBox3d& box : request.boxes) list.boxes.push_back({box});

  Eigen::AlignedBox3d bounds = request.transition >= 0 ? view::scene_bounds_at(scene, request.transition, request.time)
                                                       : view::scene_bounds_in_state(scene, request.state);
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
