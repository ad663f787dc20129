#include "reconfig/view/ghost_sampling.h"

#include <algorithm>
#include <cassert>

namespace reconfig::view {

std::vector<GhostSample> ghost_samples(const GhostRequest& request) {
  assert(request.count >= 0 && request.spacing > 0);
  constexpr double kEps = 1e-12;
  std::vector<GhostSample> samples;
  for (int k = 1; k <= request.count; ++k) {
    const double weight = 1.0 - static_cast<double>(k - 1) / request.count;
    const double before = request.current - k * request.spacing;
    const double after = request.current + k * request.spacing;
    if (request.past && before >= -kEps) samples.push_back({std::max(before, 0.0), weight});
    if (request.future && after <= 1 + kEps) samples.push_back({std::min(after, 1.0), weight});
  }
  std::sort(samples.begin(), samples.end(), [](const GhostSample& a, const GhostSample& b) { return a.time < b.time; });
  return samples;
}

}  // namespace reconfig::view
