#include "collision/detail/pair_timeline.h"

namespace reconfig::collision::detail {

Affine interpolate(const Affine& p0, const Affine& p1, double s) {
  return {(1 - s) * p0.L + s * p1.L, (1 - s) * p0.x + s * p1.x};
}

Affine proxy_map(const PartProxy& proxy, double t) {
  const int k = proxy.step_of(t);
  const double t0 = proxy.times[k], t1 = proxy.times[k + 1];
  const Affine p0{proxy.poses[k].linear(), proxy.poses[k].translation()};
  const Affine p1{proxy.poses[k + 1].linear(), proxy.poses[k + 1].translation()};
  if (t <= t0) return p0;
  if (t >= t1) return p1;
  return interpolate(p0, p1, (t - t0) / (t1 - t0));
}

PairTimeline merged_timeline(const std::vector<PartProxy>& proxies, int a, int b, double t0, double t1) {
  PairTimeline line;
  line.a = a;
  line.b = b;
  std::vector<double> times = {t0, t1};
  for (int part : {a, b})
    for (double t : proxies[part].times)
      if (t > t0 && t < t1) times.push_back(t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  line.times = times;
  for (int side = 0; side < 2; ++side) {
    const PartProxy& proxy = proxies[side == 0 ? a : b];
    for (double t : times) line.maps[side].push_back(proxy_map(proxy, t));
    for (const Affine& m : line.maps[side]) line.moving[side] = line.moving[side] || !(m == line.maps[side][0]);
  }
  return line;
}

}  // namespace reconfig::collision::detail
