#include "reconfig/view/scene_bounds.h"

#include <cassert>

#include "reconfig/geometry/bounding_box.h"

namespace reconfig::view {
namespace {

void extend(Eigen::AlignedBox3d& box, const Eigen::MatrixX3d& V) { box.extend(geometry::bounding_box(V)); }

}  // namespace

Eigen::AlignedBox3d scene_bounds_at(const scene::Reconfigurable& scene, int transition, double t) {
  Eigen::AlignedBox3d box;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) extend(box, scene.posed_vertices(transition, p, t));
  return box;
}

Eigen::AlignedBox3d scene_bounds_in_state(const scene::Reconfigurable& scene, int state) {
  Eigen::AlignedBox3d box;
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) extend(box, scene.posed_vertices_in_state(state, p));
  return box;
}

Eigen::AlignedBox3d scene_bounds_over(const scene::Reconfigurable& scene, int transition, int samples) {
  assert(samples >= 2);
  Eigen::AlignedBox3d box;
  for (int i = 0; i < samples; ++i) box.extend(scene_bounds_at(scene, transition, static_cast<double>(i) / (samples - 1)));
  return box;
}

}  // namespace reconfig::view
