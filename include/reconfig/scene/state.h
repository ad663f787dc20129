#pragma once
/// @file
/// A state of the reconfigurable: one pose per part (a node of the state graph).

#include <map>
#include <string>

#include "reconfig/motion/pose.h"

namespace reconfig::scene {

struct State {
  std::string name;
  /// Pose of each part by part name; a part not listed rests at the identity pose.
  std::map<std::string, motion::Pose> poses;

  /// The pose of `part` in this state (identity if not listed).
  motion::Pose pose_of(const std::string& part) const;
};

}  // namespace reconfig::scene
