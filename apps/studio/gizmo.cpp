#include "gizmo.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace reconfig::studio {

bool is_rotation(GizmoHandle handle) {
  return handle == GizmoHandle::kRotateX || handle == GizmoHandle::kRotateY || handle == GizmoHandle::kRotateZ;
}

Eigen::Vector3d handle_axis(GizmoHandle handle) {
  switch (handle) {
    case GizmoHandle::kMoveX:
    case GizmoHandle::kRotateX: return Eigen::Vector3d::UnitX();
    case GizmoHandle::kMoveY:
    case GizmoHandle::kRotateY: return Eigen::Vector3d::UnitY();
    case GizmoHandle::kMoveZ:
    case GizmoHandle::kRotateZ: return Eigen::Vector3d::UnitZ();
    case GizmoHandle::kNone: break;
  }
  return Eigen::Vector3d::Zero();
}

Gizmo Gizmo::sized_for(const view::Camera& camera, int height, const Eigen::Vector3d& center, double pixels) {
  const double depth = std::max((center - camera.eye()).dot(camera.forward()), camera.near_plane);
  const double world_per_pixel = 2 * depth * std::tan(camera.fov_y / 2) / std::max(height, 1);
  Gizmo gizmo;
  gizmo.center = center;
  gizmo.arrow_length = pixels * world_per_pixel;
  gizmo.ring_radius = 0.75 * gizmo.arrow_length;
  return gizmo;
}

std::vector<Eigen::Vector3d> Gizmo::shape(GizmoHandle handle, int segments) const {
  const Eigen::Vector3d axis = handle_axis(handle);
  if (!is_rotation(handle)) return {center, center + arrow_length * axis};
  // Two unit vectors spanning the ring's plane.
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i <= segments; ++i) {
    const double a = 2 * M_PI * i / segments;
    ring.push_back(center + ring_radius * (std::cos(a) * u + std::sin(a) * v));
  }
  return ring;
}

namespace {

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + s * ab - p).norm();
}

}  // namespace

GizmoHandle Gizmo::hit(const view::Camera& camera, int width, int height, const Eigen::Vector2d& mouse,
                       double tolerance) const {
  GizmoHandle best = GizmoHandle::kNone;
  double best_distance = tolerance;
  for (const GizmoHandle handle : {GizmoHandle::kMoveX, GizmoHandle::kMoveY, GizmoHandle::kMoveZ,
                                   GizmoHandle::kRotateX, GizmoHandle::kRotateY, GizmoHandle::kRotateZ}) {
    const double distance = pixel_distance_to_polyline(camera, width, height, shape(handle, 48), mouse);
    if (distance < best_distance) {
      best_distance = distance;
      best = handle;
    }
  }
  return best;
}

double pixel_distance_to_polyline(const view::Camera& camera, int width, int height,
                                  const std::vector<Eigen::Vector3d>& points, const Eigen::Vector2d& mouse) {
  double nearest = std::numeric_limits<double>::infinity();
  Eigen::Vector2d previous = Eigen::Vector2d::Zero();
  bool drawn_before = false;  // whether `previous` is the point before's pixel
  for (const Eigen::Vector3d& point : points) {
    const std::optional<view::Projection> projected = view::project_to_pixel(camera, width, height, point);
    if (projected && drawn_before) nearest = std::min(nearest, distance_to_segment(mouse, previous, projected->pixel));
    drawn_before = projected.has_value();
    if (projected) previous = projected->pixel;
  }
  return nearest;
}

std::optional<double> closest_axis_parameter(const view::Ray& ray, const Eigen::Vector3d& center,
                                             const Eigen::Vector3d& axis) {
  // Minimize |center + s·axis − (origin + r·d)| over s and r (both lines unit-direction).
  const Eigen::Vector3d w = center - ray.origin;
  const double b = axis.dot(ray.direction);
  const double denominator = 1 - b * b;
  if (denominator < 1e-6) return std::nullopt;
  return (b * w.dot(ray.direction) - w.dot(axis)) / denominator;
}

std::optional<double> ring_angle(const view::Ray& ray, const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                                 const Eigen::Vector3d& reference) {
  const std::optional<double> s = view::ray_plane(ray, center, axis);
  if (!s) return std::nullopt;
  const Eigen::Vector3d offset = ray.at(*s) - center;
  const Eigen::Vector3d u = reference.normalized(), v = axis.cross(u);
  return std::atan2(offset.dot(v), offset.dot(u));
}

motion::Pose GizmoDrag::pose_for(const view::Ray& ray) const {
  const Eigen::Vector3d axis = handle_axis(handle);
  motion::Pose pose = start_pose;
  if (handle == GizmoHandle::kNone) return pose;
  if (!is_rotation(handle)) {
    const auto s0 = closest_axis_parameter(start_ray, center, axis);
    const auto s1 = closest_axis_parameter(ray, center, axis);
    if (s0 && s1) pose.translation += (*s1 - *s0) * axis;
    return pose;
  }
  const Eigen::Vector3d reference = axis.unitOrthogonal();
  const auto a0 = ring_angle(start_ray, center, axis, reference);
  const auto a1 = ring_angle(ray, center, axis, reference);
  if (!a0 || !a1) return pose;
  // Rotating about the pivot's current position: the pivot stays, so only R changes.
  pose.rotation = (Eigen::AngleAxisd(*a1 - *a0, axis) * start_pose.rotation).normalized();
  return pose;
}

}  // namespace reconfig::studio
