#include "frame_times.h"

#include <algorithm>
#include <numeric>

namespace reconfig::studio {

FrameTimes summarize_frame_times(const std::vector<double>& milliseconds) {
  FrameTimes stats;
  if (milliseconds.empty()) return stats;
  std::vector<double> sorted = milliseconds;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  stats.frames = static_cast<int>(n);
  stats.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / static_cast<double>(n);
  stats.median = sorted[n / 2];
  stats.p95 = sorted[std::min(n - 1, n * 95 / 100)];
  stats.max = sorted.back();
  return stats;
}

}  // namespace reconfig::studio
