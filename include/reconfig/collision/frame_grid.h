#pragma once
/// @file
/// The frames of a transition: the fixed grid of time in which the detector gathers contacts
/// (reconfigurables §4.1, "consolidation over small stretches in time").
///
/// Frame k is the half-open stretch (k·w, (k+1)·w] of [0, 1], the first one closed at 0
/// ([0, w]) and the last one cut at 1. A contact lasting some time belongs to every frame it
/// overlaps for a positive time, clipped to it; a contact at a single instant t belongs to the
/// one frame holding t. So every instant of [0, 1] lies in exactly one frame, and an instant
/// contact on a frame boundary belongs to the frame on its left.

#include <algorithm>
#include <utility>

namespace reconfig::collision {

class FrameGrid {
 public:
  /// @param width  frame length w, in (0, 1]
  explicit FrameGrid(double width);

  double width() const { return width_; }
  int count() const { return count_; }
  double lo(int k) const { return std::min(1.0, k * width_); }  ///< start of frame k
  double hi(int k) const { return k + 1 == count_ ? 1.0 : std::min(1.0, (k + 1) * width_); }  ///< end of frame k

  /// The frame holding instant t ∈ [0, 1].
  int frame_of(double t) const;
  /// The frames a time range [t0, t1] (t0 < t1) overlaps for a positive time: first and last.
  std::pair<int, int> frames_overlapping(double t0, double t1) const;

 private:
  double width_;
  int count_;
};

}  // namespace reconfig::collision
