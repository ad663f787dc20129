#pragma once
// Locating a time among strictly increasing key times.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace reconfig::motion::detail {

/// Where a time falls among key times s_0 < s_1 < ... < s_{n-1}.
struct KeyLocation {
  enum class Region { kBefore, kInside, kAfter, kSingle };
  Region region;
  std::size_t segment = 0;  ///< j with s_j <= t < s_{j+1} (kInside); key index otherwise
  double f = 0.0;           ///< (t − s_j) / (s_{j+1} − s_j) in [0, 1) (kInside)
};

/// Right-continuous: a time equal to s_j (j < n−1) belongs to segment j with f = 0; a time
/// >= s_{n-1} is kAfter (segment = n−1).
inline KeyLocation locate(const std::vector<double>& times, double t) {
  KeyLocation loc;
  const std::size_t n = times.size();
  if (n == 1) {
    loc.region = KeyLocation::Region::kSingle;
    return loc;
  }
  if (t < times.front()) {
    loc.region = KeyLocation::Region::kBefore;
    loc.segment = 0;
    return loc;
  }
  if (t >= times.back()) {
    loc.region = KeyLocation::Region::kAfter;
    loc.segment = n - 1;
    return loc;
  }
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t j = static_cast<std::size_t>(it - times.begin()) - 1;
  loc.region = KeyLocation::Region::kInside;
  loc.segment = j;
  loc.f = (t - times[j]) / (times[j + 1] - times[j]);
  return loc;
}

}  // namespace reconfig::motion::detail
