#include "support/random_scene.h"

#include <random>

#include "reconfig/geometry/primitives.h"
#include "reconfig/scene/part.h"

namespace reconfig::testing {

scene::Reconfigurable random_scene(std::uint32_t seed, const RandomSceneOptions& options) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal(0, 1);  // own generator only: scenes do not depend on std::rand
  const auto point = [&]() -> Eigen::Vector3d {  // a value, not an Eigen expression of temporaries
    return Eigen::Vector3d(unit(random), unit(random), unit(random)) * 2 * options.spread -
           Eigen::Vector3d::Constant(options.spread);
  };
  scene::Reconfigurable scene;
  scene.states = {{"start", {}}, {"end", {}}};
  scene::Transition transition{"move", "start", "end", true, {}};
  for (int p = 0; p < options.parts; ++p) {
    scene::Part part;
    part.name = "part" + std::to_string(p);
    switch (p % 3) {
      case 0: part.source = scene::BoxPrimitive{Eigen::Vector3d(0.2 + 0.4 * unit(random), 0.1 + 0.3 * unit(random), 0.05 + 0.2 * unit(random))}; break;
      case 1: part.source = scene::CylinderPrimitive{0.05 + 0.15 * unit(random), 0.2 + 0.5 * unit(random)}; break;
      default: part.source = scene::SpherePrimitive{0.1 + 0.2 * unit(random)}; break;
    }
    part.mesh = scene::Part::primitive_mesh(part.source);
    if (const auto* sphere = std::get_if<scene::SpherePrimitive>(&part.source))
      part.mesh = geometry::make_sphere(sphere->radius, options.sphere_subdivisions);
    if (const auto* cylinder = std::get_if<scene::CylinderPrimitive>(&part.source))
      part.mesh = geometry::make_cylinder(cylinder->radius, cylinder->height, options.cylinder_segments);
    part.center = scene::part_center(part.mesh);
    const Eigen::Vector3d a = point();
    const Eigen::Quaterniond qa = Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized();
    motion::Pose start{qa, a};
    if (p >= options.moving) {
      scene.states[0].poses[part.name] = start;
      scene.states[1].poses[part.name] = start;
      scene.parts.push_back(part);
      continue;
    }
    const Eigen::Vector3d b = point();
    scene::KeyframedTrack track;
    track.translation = {{0.0, a, a, a + (point() - a) * 0.5}, {1.0, b, b + (point() - b) * 0.5, b}};
    const Eigen::Vector3d axis = Eigen::Vector3d(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5).normalized();
    const double turn = options.max_turn * unit(random);
    for (int k = 0; k < options.rotation_keys; ++k) {
      const double f = static_cast<double>(k) / (options.rotation_keys - 1);
      track.rotation.push_back({f, Eigen::Quaterniond(Eigen::AngleAxisd(turn * f, axis)) * qa});
    }
    scene.states[0].poses[part.name] = start;
    scene.states[1].poses[part.name] = {track.rotation.back().rotation, b};
    transition.tracks[part.name] = track;
    scene.parts.push_back(part);
  }
  scene.transitions.push_back(transition);
  return scene;
}

}  // namespace reconfig::testing
