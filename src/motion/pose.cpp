#include "reconfig/motion/pose.h"

namespace reconfig::motion {

Eigen::Vector3d Pose::apply(const Eigen::Vector3d& center, const Eigen::Vector3d& p) const {
  return rotation * (p - center) + center + translation;
}

Eigen::Isometry3d Pose::to_isometry(const Eigen::Vector3d& center) const {
  // v = R p + (c − R c + x)
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  const Eigen::Matrix3d R = rotation.normalized().toRotationMatrix();
  M.linear() = R;
  M.translation() = center - R * center + translation;
  return M;
}

Pose Pose::from_isometry(const Eigen::Isometry3d& M, const Eigen::Vector3d& center) {
  Pose pose;
  pose.rotation = Eigen::Quaterniond(M.rotation()).normalized();
  const Eigen::Matrix3d R = pose.rotation.toRotationMatrix();
  // M p = R p + m  =  R (p − c) + c + x  ⇒  x = m + R c − c
  pose.translation = M.translation() + R * center - center;
  return pose;
}

}  // namespace reconfig::motion
