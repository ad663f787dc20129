#include "reconfig/sculpt/tool_motion.h"

#include <cassert>
#include <cmath>

namespace reconfig::sculpt {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

}  // namespace

ToolMotion ToolMotion::translation(const Eigen::Vector3d& d) { return {Kind::kTranslation, d, Eigen::Vector3d::Zero(), 0}; }

ToolMotion ToolMotion::scaling(double factor, const Eigen::Vector3d& center) {
  assert(factor > 0);
  return {Kind::kScale, Eigen::Vector3d::Zero(), center, factor};
}

ToolMotion ToolMotion::rotation(const Eigen::Vector3d& axis, double radians, const Eigen::Vector3d& center) {
  assert(axis.norm() > 0);
  return {Kind::kRotation, axis.normalized(), center, radians};
}

ToolMotion ToolMotion::fraction(double alpha) const {
  ToolMotion m = *this;
  if (kind == Kind::kTranslation) m.vector = alpha * vector;
  if (kind == Kind::kScale) m.amount = std::pow(amount, alpha);
  if (kind == Kind::kRotation) m.amount = alpha * amount;
  return m;
}

ToolMotion ToolMotion::inverse() const {
  ToolMotion m = *this;
  if (kind == Kind::kTranslation) m.vector = -vector;
  if (kind == Kind::kScale) m.amount = 1 / amount;
  if (kind == Kind::kRotation) m.amount = -amount;
  return m;
}

Eigen::Vector3d ToolMotion::apply(const Eigen::Vector3d& p, double alpha) const {
  switch (kind) {
    case Kind::kTranslation: return p + alpha * vector;
    case Kind::kScale: return center + std::pow(amount, alpha) * (p - center);
    case Kind::kRotation: break;
  }
  return center + Eigen::AngleAxisd(alpha * amount, vector) * (p - center);
}

Eigen::Matrix3d ToolMotion::linear(double alpha) const {
  switch (kind) {
    case Kind::kTranslation: return Eigen::Matrix3d::Identity();
    case Kind::kScale: return std::pow(amount, alpha) * Eigen::Matrix3d::Identity();
    case Kind::kRotation: break;
  }
  return Eigen::AngleAxisd(alpha * amount, vector).toRotationMatrix();
}

Eigen::Vector3d ToolMotion::velocity(const Eigen::Vector3d& p, double alpha) const {
  switch (kind) {
    case Kind::kTranslation: return vector;
    case Kind::kScale: return std::log(amount) * (apply(p, alpha) - center);
    case Kind::kRotation: break;
  }
  return amount * vector.cross(apply(p, alpha) - center);
}

ToolPose ToolMotion::apply(const ToolPose& pose, double alpha) const {
  ToolPose moved = pose;
  moved.translation = apply(pose.translation, alpha);
  if (kind == Kind::kScale) moved.scale = pose.scale * std::pow(amount, alpha);
  if (kind == Kind::kRotation)
    moved.rotation = (Eigen::Quaterniond(Eigen::AngleAxisd(alpha * amount, vector)) * pose.rotation).normalized();
  return moved;
}

Eigen::Matrix4d ToolMotion::log_matrix() const {
  Eigen::Matrix4d log = Eigen::Matrix4d::Zero();
  switch (kind) {
    case Kind::kTranslation: log.topRightCorner<3, 1>() = vector; break;
    case Kind::kScale:
      log.topLeftCorner<3, 3>() = std::log(amount) * Eigen::Matrix3d::Identity();
      log.topRightCorner<3, 1>() = -std::log(amount) * center;
      break;
    case Kind::kRotation:
      log.topLeftCorner<3, 3>() = amount * cross_matrix(vector);
      log.topRightCorner<3, 1>() = -amount * cross_matrix(vector) * center;
      break;
  }
  return log;
}

}  // namespace reconfig::sculpt
