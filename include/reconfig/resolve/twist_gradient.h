#pragma once
/// @file
/// The gradient of a scalar with respect to a rigid motion of one part: a force and a torque.

#include <Eigen/Core>

namespace reconfig::resolve {

/// ∂f/∂(v, ω) for a rigid velocity field u(y) = v + ω × y of world space (ω about the world
/// origin): a small rigid motion of the part by (v, ω) changes f by `force·v + torque·ω`
/// (reconfigurables §6.4: the contact normal G_t reduced to the part's rigid degrees of freedom).
struct TwistGradient {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();

  /// Adds h, the gradient of f with respect to the position of a point y that moves with the
  /// part: the force gains h and the torque y × h.
  void add_point(const Eigen::Vector3d& y, const Eigen::Vector3d& h) {
    force += h;
    torque += y.cross(h);
  }
  TwistGradient& operator+=(const TwistGradient& other) {
    force += other.force;
    torque += other.torque;
    return *this;
  }
  TwistGradient operator*(double s) const { return {s * force, s * torque}; }
  TwistGradient operator-() const { return {-force, -torque}; }
  /// The 6-vector (force; torque).
  Eigen::Matrix<double, 6, 1> stacked() const {
    Eigen::Matrix<double, 6, 1> g;
    g << force, torque;
    return g;
  }
};

}  // namespace reconfig::resolve
