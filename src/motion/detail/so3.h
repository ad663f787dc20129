#pragma once
// Small SO(3) helpers shared by the motion module: hat map, exponential and logarithm,
// left Jacobian and its inverse, and ratios of sines that stay accurate near zero.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace reconfig::motion::detail {

inline Eigen::Matrix3d hat(const Eigen::Vector3d& w) {
  Eigen::Matrix3d W;
  W << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return W;
}

/// sin(t·h)/sin(h) for h in [0, π/2]; its limit t when h == 0.
inline double sin_ratio(double t, double h) {
  if (h == 0.0) return t;
  return std::sin(t * h) / std::sin(h);
}

/// Unit quaternion of the rotation vector w (angle |w| about w/|w|).
inline Eigen::Quaterniond quat_exp(const Eigen::Vector3d& w) {
  const double a = w.norm();
  const double half = 0.5 * a;
  // sin(a/2)/a, accurate near 0.
  const double k = a < 1e-8 ? 0.5 - a * a / 48.0 : std::sin(half) / a;
  return Eigen::Quaterniond(std::cos(half), k * w.x(), k * w.y(), k * w.z());
}

/// Rotation vector of a unit quaternion, angle in [0, π] (q and −q give the same result
/// except at exactly π, where the sign of q's vector part decides).
inline Eigen::Vector3d quat_log(Eigen::Quaterniond q) {
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d v = q.vec();
  const double n = v.norm();
  if (n == 0.0) return Eigen::Vector3d::Zero();
  const double angle = 2.0 * std::atan2(n, q.w());
  return (angle / n) * v;
}

/// Left Jacobian of SO(3): exp(w + δ) ≈ exp(J_l(w) δ) exp(w).
inline Eigen::Matrix3d left_jacobian(const Eigen::Vector3d& w) {
  const double a = w.norm();
  const Eigen::Matrix3d W = hat(w);
  double c1, c2;  // (1 − cos a)/a², (a − sin a)/a³
  if (a < 1e-4) {
    const double a2 = a * a;
    c1 = 0.5 - a2 / 24.0 + a2 * a2 / 720.0;
    c2 = 1.0 / 6.0 - a2 / 120.0 + a2 * a2 / 5040.0;
  } else {
    c1 = (1.0 - std::cos(a)) / (a * a);
    c2 = (a - std::sin(a)) / (a * a * a);
  }
  return Eigen::Matrix3d::Identity() + c1 * W + c2 * W * W;
}

/// Inverse of the left Jacobian: log(exp(δ) exp(w)) ≈ w + J_l⁻¹(w) δ. Valid for |w| < 2π.
inline Eigen::Matrix3d left_jacobian_inverse(const Eigen::Vector3d& w) {
  const double a = w.norm();
  const Eigen::Matrix3d W = hat(w);
  double c;  // 1/a² − (1 + cos a)/(2 a sin a) = 1/a² − cot(a/2)/(2a)
  if (a < 1e-4) {
    const double a2 = a * a;
    c = 1.0 / 12.0 + a2 / 720.0 + a2 * a2 / 30240.0;
  } else {
    c = 1.0 / (a * a) - std::cos(0.5 * a) / (2.0 * a * std::sin(0.5 * a));
  }
  return Eigen::Matrix3d::Identity() - 0.5 * W + c * W * W;
}

/// Bound on the distance between a unit-speed circular arc of angle ψ (radius 1) and the
/// uniform-speed chord joining its ends, over the whole arc:
/// max_h |e^{ihψ} − (1−h) − h e^{iψ}| ≤ min(ψ²/8, 2). (The difference vanishes at h = 0, 1
/// and its second derivative in h has modulus ψ², so |f(h)| ≤ ψ² h(1−h)/2.)
inline double arc_chord_deviation(double psi) {
  psi = std::abs(psi);
  return std::min(psi * psi / 8.0, 2.0);
}

}  // namespace reconfig::motion::detail
