#include "reconfig/view/view_candidates.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace reconfig::view {

Eigen::Vector3d part_displacement(const scene::Reconfigurable& scene, int transition, int part, double t0, double t1) {
  const scene::Part& p = scene.parts[part];
  const Eigen::Vector3d center_of_mass = scene::part_center(p.mesh);
  return scene.pose_at(transition, part, t1).apply(p.center, center_of_mass) -
         scene.pose_at(transition, part, t0).apply(p.center, center_of_mass);
}

std::optional<std::array<Eigen::Vector3d, 2>> motion_normal_directions(const Eigen::Vector3d& rA,
                                                                       const Eigen::Vector3d& rB, double min_sine,
                                                                       double min_ratio) {
  const double a = rA.norm(), b = rB.norm();
  if (a == 0 || b == 0 || std::min(a, b) < min_ratio * std::max(a, b)) return std::nullopt;
  const Eigen::Vector3d normal = rA.cross(rB);
  if (normal.norm() < min_sine * a * b) return std::nullopt;
  const Eigen::Vector3d n = normal.normalized();
  return std::array<Eigen::Vector3d, 2>{n, -n};
}

std::vector<Eigen::Vector3d> random_view_directions(int count, bool northern_hemisphere, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> height(northern_hemisphere ? 0.0 : -1.0, 1.0), azimuth(-M_PI, M_PI);
  std::vector<Eigen::Vector3d> directions;
  directions.reserve(std::max(count, 0));
  for (int i = 0; i < count; ++i) {
    // Archimedes: z uniform and azimuth uniform give points uniform on the sphere's area.
    const double z = height(random), phi = azimuth(random), r = std::sqrt(std::max(0.0, 1 - z * z));
    directions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return directions;
}

std::vector<Eigen::Vector3d> axis_view_directions(bool northern_hemisphere) {
  std::vector<Eigen::Vector3d> directions = {Eigen::Vector3d::UnitX(),  -Eigen::Vector3d::UnitX(),
                                             Eigen::Vector3d::UnitY(),  -Eigen::Vector3d::UnitY(),
                                             Eigen::Vector3d::UnitZ()};
  if (!northern_hemisphere) directions.push_back(-Eigen::Vector3d::UnitZ());
  return directions;
}

}  // namespace reconfig::view
