#include "reconfig/sculpt/tool.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "reconfig/geometry/bounding_box.h"
#include "reconfig/sculpt/falloff.h"

namespace reconfig::sculpt {
namespace {

double sphere_distance(const Eigen::Vector3d& x, double radius, Eigen::Vector3d* gradient) {
  const double r = x.norm();
  if (gradient) *gradient = r > 0 ? Eigen::Vector3d(x / r) : Eigen::Vector3d::UnitZ();
  return r - radius;
}

double box_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& half, Eigen::Vector3d* gradient) {
  const Eigen::Vector3d q = x.cwiseAbs() - half;
  const Eigen::Vector3d outside = q.cwiseMax(0.0);
  const double out = outside.norm();
  if (out > 0) {
    if (gradient) *gradient = outside.cwiseProduct(x.cwiseSign()) / out;
    return out;
  }
  int axis = 0;
  const double in = q.maxCoeff(&axis);
  if (gradient) *gradient = Eigen::Vector3d::Unit(axis) * (x[axis] < 0 ? -1.0 : 1.0);
  return in;
}

double capsule_distance(const Eigen::Vector3d& x, double radius, double half_length, Eigen::Vector3d* gradient) {
  const Eigen::Vector3d nearest(0, 0, std::clamp(x.z(), -half_length, half_length));
  return sphere_distance(x - nearest, radius, gradient);
}

/// (‖x ⊘ r‖ − 1)·min r: zero on the ellipsoid, 1-Lipschitz (|∇| = min r ‖x ⊘ r²‖ / ‖x ⊘ r‖ ≤ 1).
double ellipsoid_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& radii, Eigen::Vector3d* gradient) {
  const double r_min = radii.minCoeff();
  const Eigen::Vector3d u = x.cwiseQuotient(radii);
  const double length = u.norm();
  if (gradient)
    *gradient = length > 0 ? Eigen::Vector3d(r_min * u.cwiseQuotient(radii) / length) : Eigen::Vector3d::UnitZ();
  return (length - 1) * r_min;
}

}  // namespace

Tool::Tool(ToolShape shape, const Eigen::Vector3d& size, const Eigen::Vector3d& center, double coating)
    : shape_(shape), size_(size), coating_(coating) {
  assert(coating > 0);
  pose_.translation = center;
  Eigen::Vector3d half = size;
  if (shape == ToolShape::kSphere) half.setConstant(size.x());
  if (shape == ToolShape::kCapsule) half = Eigen::Vector3d(size.x(), size.x(), size.x() + size.z());
  local_box_ = Eigen::AlignedBox3d(-half, half);
}

Tool Tool::sphere(double radius, const Eigen::Vector3d& center, double coating) {
  return Tool(ToolShape::kSphere, Eigen::Vector3d::Constant(radius), center, coating);
}

Tool Tool::box(const Eigen::Vector3d& size, const Eigen::Vector3d& center, double coating) {
  return Tool(ToolShape::kBox, size / 2, center, coating);
}

Tool Tool::capsule(double radius, double length, const Eigen::Vector3d& center, double coating) {
  return Tool(ToolShape::kCapsule, Eigen::Vector3d(radius, radius, length / 2), center, coating);
}

Tool Tool::ellipsoid(const Eigen::Vector3d& radii, const Eigen::Vector3d& center, double coating) {
  return Tool(ToolShape::kEllipsoid, radii, center, coating);
}

Tool Tool::baked(const geometry::Mesh& mesh, double coating) {
  Tool tool(ToolShape::kMesh, Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero(), coating);
  tool.baked_ = std::make_shared<const geometry::MeshSignedDistance>(mesh);
  tool.local_box_ = geometry::bounding_box(mesh.V);
  return tool;
}

double Tool::local_distance(const Eigen::Vector3d& x, Eigen::Vector3d* gradient) const {
  switch (shape_) {
    case ToolShape::kSphere: return sphere_distance(x, size_.x(), gradient);
    case ToolShape::kBox: return box_distance(x, size_, gradient);
    case ToolShape::kCapsule: return capsule_distance(x, size_.x(), size_.z(), gradient);
    case ToolShape::kEllipsoid: return ellipsoid_distance(x, size_, gradient);
    case ToolShape::kMesh: break;
  }
  const double reach = coating_ / pose_.scale;  // beyond it φ = 0 whatever the exact distance
  const geometry::MeshSignedDistance::Query q = baked_->query(x, reach);
  if (q.triangle < 0) {
    if (gradient) gradient->setZero();
    return reach;
  }
  if (gradient) {
    const Eigen::Vector3d away = x - q.nearest;
    const double length = away.norm();
    *gradient = q.distance > 0 && length > 0 ? Eigen::Vector3d(away / length) : Eigen::Vector3d::Zero();
  }
  return q.distance;
}

double Tool::distance(const Eigen::Vector3d& p) const {
  return pose_.scale * local_distance(pose_.to_tool(p), nullptr);
}

double Tool::distance(const Eigen::Vector3d& p, Eigen::Vector3d& gradient) const {
  if (shape_ == ToolShape::kSphere) {  // the common tool, without turning p into the tool's frame
    const double d = sphere_distance(p - pose_.translation, pose_.scale * size_.x(), &gradient);
    if (d <= 0) gradient.setZero();
    return d;
  }
  Eigen::Vector3d local_gradient;
  const double d = pose_.scale * local_distance(pose_.to_tool(p), &local_gradient);
  gradient = d > 0 ? Eigen::Vector3d(pose_.rotation * local_gradient) : Eigen::Vector3d::Zero();
  return d;
}

double Tool::field(const Eigen::Vector3d& p) const { return falloff(distance(p), coating_); }

double Tool::field(const Eigen::Vector3d& p, Eigen::Vector3d& gradient) const {
  const double d = distance(p, gradient);
  gradient *= falloff_slope(d, coating_);
  return falloff(d, coating_);
}

Eigen::AlignedBox3d Tool::field_box() const {
  // The ellipsoid's field reaches λ where ‖x ⊘ r‖ = 1 + λ / (scale · min r): a bigger ellipsoid.
  const bool ellipsoid = shape_ == ToolShape::kEllipsoid;
  const double grow = ellipsoid ? 1 + coating_ / (pose_.scale * size_.minCoeff()) : 1;
  Eigen::AlignedBox3d box;
  for (int corner = 0; corner < 8; ++corner)
    box.extend(pose_.to_world(grow * local_box_.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner))));
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(ellipsoid ? 0.0 : coating_);
  return {box.min() - margin, box.max() + margin};
}

}  // namespace reconfig::sculpt
