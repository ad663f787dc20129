#include "resolve/detail/line_search.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace reconfig::resolve::detail {
namespace {

constexpr int kHalvings = 16;
constexpr int kBisections = 8;
constexpr int kGoldenSteps = 12;
constexpr double kInvPhi = 0.6180339887498949;

/// The smallest step in (lo, hi] found to have zero energy (energy(hi) == 0).
double first_zero(const std::function<double(double)>& energy, double lo, double hi) {
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (energy(mid) == 0 ? hi : lo) = mid;
  }
  return hi;
}

/// Golden-section search for the minimum of `energy` on [lo, hi]: (step, energy).
std::pair<double, double> golden_section(const std::function<double(double)>& energy, double lo, double hi) {
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double f1 = energy(x1), f2 = energy(x2);
  for (int i = 0; i < kGoldenSteps; ++i) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - kInvPhi * (hi - lo), f1 = energy(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + kInvPhi * (hi - lo), f2 = energy(x2);
    }
  }
  return f1 < f2 ? std::pair{x1, f1} : std::pair{x2, f2};
}

}  // namespace

double line_search(const std::function<double(double)>& energy, double e0, double reach, double clearance) {
  std::vector<double> steps, values;
  for (int k = 0; k < kHalvings; ++k) {
    steps.push_back(reach / std::pow(2.0, k));
    values.push_back(energy(steps.back()));
  }
  int best = static_cast<int>(std::min_element(values.begin(), values.end()) - values.begin());
  if (!(values[best] < e0)) return 0;
  if (values[best] == 0) {
    while (best + 1 < kHalvings && values[best + 1] == 0) ++best;  // the shortest zero step scanned
    const double zero = first_zero(energy, best + 1 < kHalvings ? steps[best + 1] : 0.0, steps[best]);
    const double cleared = std::min(reach, zero + clearance);
    return energy(cleared) == 0 ? cleared : zero;
  }
  const double shorter = best + 1 < kHalvings ? steps[best + 1] : 0.0;
  const auto [step, value] = golden_section(energy, shorter, best > 0 ? steps[best - 1] : reach);
  return value < values[best] ? step : steps[best];
}

}  // namespace reconfig::resolve::detail
