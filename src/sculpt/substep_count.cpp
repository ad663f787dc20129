#include "reconfig/sculpt/substep_count.h"

#include <algorithm>
#include <cmath>

#include "reconfig/sculpt/falloff.h"

namespace reconfig::sculpt {
namespace {

/// max_k ‖(log M) p_k‖ over the corners of `box`.
double largest_log_displacement(const ToolMotion& motion, const Eigen::AlignedBox3d& box) {
  const Eigen::Matrix4d log = motion.log_matrix();
  double largest = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
    largest = std::max(largest, (log.topLeftCorner<3, 3>() * p + log.topRightCorner<3, 1>()).norm());
  }
  return largest;
}

}  // namespace

double foldover_bound(const std::vector<MovingTool>& tools) {
  double bound = 0;
  for (const MovingTool& moving : tools) {
    Tool end = moving.tool;
    end.set_pose(moving.motion.apply(moving.tool.pose(), 1.0));
    const double reach = std::max(largest_log_displacement(moving.motion, moving.tool.field_box()),
                                  largest_log_displacement(moving.motion, end.field_box()));
    bound += kFalloffSteepestSlope / moving.tool.coating() * reach;
  }
  return bound;
}

int substep_count(const std::vector<MovingTool>& tools) {
  return std::max(1, static_cast<int>(std::floor(foldover_bound(tools))) + 1);
}

}  // namespace reconfig::sculpt
