#include "screw_sweep.h"

#include <vector>

namespace reconfig::cli {

ScrewSweep screw_sweep(const geometry::Mesh& part, const sweep::RelativeMotion& motion, double tolerance) {
  ScrewSweep result;
  const std::vector<double> times = motion.time_samples(tolerance, result.motion_error);
  std::vector<motion::ScrewMotion> screws;
  for (std::size_t k = 0; k + 1 < times.size(); ++k) screws.emplace_back(motion.at(times[k]), motion.at(times[k + 1]));
  if (screws.empty()) screws.emplace_back(motion.at(motion.start_time()), motion.at(motion.end_time()));
  result.screws = static_cast<int>(screws.size());
  result.envelope = sweep::screw_envelope(sweep::EnvelopePart(part), screws);
  return result;
}

}  // namespace reconfig::cli
