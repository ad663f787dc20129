#include "reconfig/resolve/shape_cache.h"

namespace reconfig::resolve {

const PartShape& ShapeCache::shape(const scene::Reconfigurable& scene, int part) {
  auto& slot = shapes_[part];
  if (!slot) slot = std::make_unique<PartShape>(scene.parts.at(part).mesh);
  return *slot;
}

}  // namespace reconfig::resolve
