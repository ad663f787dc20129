#include "reconfig/scene/dirty_set.h"

#include <algorithm>

namespace reconfig::scene {

void DirtySet::merge(const DirtySet& other) {
  ranges.insert(ranges.end(), other.ranges.begin(), other.ranges.end());
  for (int part : other.geometry_changed)
    if (std::find(geometry_changed.begin(), geometry_changed.end(), part) == geometry_changed.end())
      geometry_changed.push_back(part);
  structure_changed = structure_changed || other.structure_changed;
  for (int transition : other.added_transitions)
    if (std::find(added_transitions.begin(), added_transitions.end(), transition) == added_transitions.end())
      added_transitions.push_back(transition);
}

}  // namespace reconfig::scene
