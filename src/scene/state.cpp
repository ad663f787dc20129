#include "reconfig/scene/state.h"

namespace reconfig::scene {

motion::Pose State::pose_of(const std::string& part) const {
  const auto it = poses.find(part);
  return it == poses.end() ? motion::Pose{} : it->second;
}

}  // namespace reconfig::scene
