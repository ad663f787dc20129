#pragma once
/// @file
/// A transition between two states: an edge of the state graph, choreographed on [0, 1].

#include <map>
#include <optional>
#include <string>

#include "reconfig/scene/linkage_drive.h"
#include "reconfig/scene/track.h"

namespace reconfig::scene {

struct Transition {
  std::string name;
  std::string from, to;     ///< state names
  bool bidirectional = true;  ///< can be played backwards
  /// Motion of each animated part by part name. A part without a track holds its pose (and
  /// has the same pose in both states).
  std::map<std::string, Track> tracks;
  /// A planar linkage that drives some parts (linkage_drive.h); their tracks in `tracks` are
  /// compiled from it (compile_linkage_drive) and saving writes the drive instead of them.
  std::optional<LinkageDrive> linkage = std::nullopt;
};

}  // namespace reconfig::scene
