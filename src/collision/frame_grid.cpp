#include "reconfig/collision/frame_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace reconfig::collision {

FrameGrid::FrameGrid(double width) : width_(width) {
  if (!(width > 0 && width <= 1)) throw std::invalid_argument("frame width must lie in (0, 1]");
  count_ = std::max(1, static_cast<int>(std::ceil(1 / width - 1e-9)));
}

int FrameGrid::frame_of(double t) const {
  // The estimate can be one off through rounding; the bounds decide.
  int k = std::clamp(static_cast<int>(std::ceil(t / width_)) - 1, 0, count_ - 1);
  while (k > 0 && t <= lo(k)) --k;
  while (k + 1 < count_ && t > hi(k)) ++k;
  return k;
}

std::pair<int, int> FrameGrid::frames_overlapping(double t0, double t1) const {
  int first = std::clamp(static_cast<int>(std::floor(t0 / width_)), 0, count_ - 1);
  while (first > 0 && lo(first) > t0) --first;
  while (first + 1 < count_ && hi(first) <= t0) ++first;
  return {first, frame_of(t1)};
}

}  // namespace reconfig::collision
