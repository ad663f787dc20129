#include "reconfig/collision/contact_tolerance.h"

#include <algorithm>

namespace reconfig::collision {

double design_size(const scene::Reconfigurable& scene) {
  double size = 0;
  for (const scene::Part& part : scene.parts)
    if (part.mesh.V.size() > 0) size = std::max(size, part.mesh.V.cwiseAbs().maxCoeff());
  return size > 0 ? size : 1.0;
}

double contact_tolerance(const scene::Reconfigurable& scene, double contact) {
  return contact > 0 ? contact : kDefaultContact * design_size(scene);
}

}  // namespace reconfig::collision
