#pragma once
/// @file
/// Summary statistics of measured frame times (the studio's --frame-times and bench_studio).

#include <vector>

namespace reconfig::studio {

struct FrameTimes {
  int frames = 0;
  double mean = 0, median = 0, p95 = 0, max = 0;  ///< milliseconds
};

/// Statistics of frame durations in milliseconds (all zero for none). The median and 95th
/// percentile are the sorted samples at indices n/2 and min(n−1, 95n/100).
FrameTimes summarize_frame_times(const std::vector<double>& milliseconds);

}  // namespace reconfig::studio
