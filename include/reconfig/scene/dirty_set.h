#pragma once
/// @file
/// What an edit invalidated: the input of incremental collision detection.

#include <vector>

namespace reconfig::scene {

/// A part whose motion or geometry changed over [t0, t1] of one transition.
struct DirtyRange {
  int transition = 0;
  int part = 0;
  double t0 = 0, t1 = 1;
  bool operator==(const DirtyRange&) const = default;
};

/// Everything one edit changed. Ranges may overlap; consumers take their union.
struct DirtySet {
  std::vector<DirtyRange> ranges;
  /// Parts whose rest geometry changed (their spatial hierarchies must be rebuilt).
  std::vector<int> geometry_changed;
  /// The list of parts, states or transitions itself changed: rebuild everything.
  bool structure_changed = false;
  /// Transitions appended to the end of the list (their indices): detect those from scratch,
  /// while the results of the others stand.
  std::vector<int> added_transitions;

  bool empty() const {
    return ranges.empty() && geometry_changed.empty() && !structure_changed && added_transitions.empty();
  }
  void merge(const DirtySet& other);
};

}  // namespace reconfig::scene
