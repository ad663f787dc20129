#include "reconfig/collision/tolerance_scale.h"

#include <fmt/format.h>

namespace reconfig::collision {

std::string tolerance_scale_problem(const scene::Reconfigurable& scene, const std::vector<int>& transitions,
                                    double tolerance) {
  double radius = 0;
  std::string largest;
  const auto visit = [&](const scene::Transition& transition) {
    for (const auto& [name, track] : transition.tracks) {
      const int part = scene.find_part(name);
      if (part < 0 || scene.parts[part].mesh.V.rows() == 0) continue;
      const scene::Part& p = scene.parts[part];
      const double r = (p.mesh.V.rowwise() - p.center.transpose()).rowwise().norm().maxCoeff();
      if (r > radius) std::tie(radius, largest) = std::pair{r, name};
    }
  };
  if (transitions.empty())
    for (const scene::Transition& transition : scene.transitions) visit(transition);
  for (const int t : transitions) visit(scene.transitions[t]);
  if (!(radius > kMaxSizeToTolerance * tolerance)) return "";
  return fmt::format("a tolerance of {:g} is too fine for part \"{}\", which reaches {:g} from its center ({:.0e} "
                     "times the tolerance, more than {:.0e}): its time steps would take minutes and gigabytes; use a "
                     "tolerance of at least {:g}",
                     tolerance, largest, radius, radius / tolerance, kMaxSizeToTolerance, radius / kMaxSizeToTolerance);
}

}  // namespace reconfig::collision
