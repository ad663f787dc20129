#include "reconfig/view/working_side.h"

#include <cmath>

#include "reconfig/geometry/bounding_box.h"

namespace reconfig::view {
namespace {

constexpr double kDegree = M_PI / 180;
constexpr int kSamples = 8;

Eigen::Vector2d center_xy(const Eigen::MatrixX3d& V) {
  if (V.rows() == 0) return Eigen::Vector2d::Zero();
  return geometry::bounding_box(V).center().head<2>();
}

Eigen::Vector2d over_first_transition(const scene::Reconfigurable& scene) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p) {
    const Eigen::Vector2d start = center_xy(scene.posed_vertices(0, p, 0));
    for (int i = 1; i <= kSamples; ++i)
      sum += center_xy(scene.posed_vertices(0, p, static_cast<double>(i) / kSamples)) - start;
  }
  return sum;
}

Eigen::Vector2d between_states(const scene::Reconfigurable& scene) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int s = 1; s < static_cast<int>(scene.states.size()); ++s)
    for (int p = 0; p < static_cast<int>(scene.parts.size()); ++p)
      sum += center_xy(scene.posed_vertices_in_state(s, p)) - center_xy(scene.posed_vertices_in_state(0, p));
  return sum;
}

}  // namespace

Eigen::Vector2d working_direction(const scene::Reconfigurable& scene) {
  return scene.transitions.empty() ? between_states(scene) : over_first_transition(scene);
}

void aim_at_working_side(Camera& camera, const scene::Reconfigurable& scene) {
  const Eigen::Vector2d direction = working_direction(scene);
  camera.yaw = direction.norm() > 1e-9 ? std::atan2(direction.y(), direction.x()) - 30 * kDegree : 60 * kDegree;
  camera.pitch = 25 * kDegree;
}

}  // namespace reconfig::view
