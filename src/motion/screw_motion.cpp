#include "reconfig/motion/screw_motion.h"

#include "motion/detail/so3.h"

#include <cassert>
#include <cmath>

namespace reconfig::motion {

namespace {
constexpr double kHalfTurnTolerance = 1e-12;  // |w| below this: exactly 180°
}  // namespace

ScrewMotion::ScrewMotion()
    : A_(Eigen::Isometry3d::Identity()),
      B_(Eigen::Isometry3d::Identity()),
      s_(Eigen::Vector3d::UnitZ()),
      p_(Eigen::Vector3d::Zero()),
      o_perp_(Eigen::Vector3d::Zero()) {}

ScrewMotion::ScrewMotion(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B)
    : A_(A), B_(B) {
  assert(A.linear().determinant() > 0.0 && B.linear().determinant() > 0.0);
  const Eigen::Quaterniond qa(A.linear());
  const Eigen::Quaterniond qb(B.linear());
  Eigen::Quaterniond q = (qb * qa.conjugate()).normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // minimal angle

  Eigen::Vector3d v = q.vec();
  double w = q.w();
  if (w <= kHalfTurnTolerance && v.norm() > 0.0) {
    // Exactly a half turn: fix the angle to π and pick the axis sign canonically.
    w = 0.0;
    v.normalize();
    Eigen::Index k = 0;
    v.cwiseAbs().maxCoeff(&k);  // first index of the largest magnitude
    if (v[k] < 0.0) v = -v;
  }
  // D's translation, consistent with the rotation actually used for D.
  const Eigen::Quaterniond qd(w, v.x(), v.y(), v.z());
  const Eigen::Vector3d o = B.translation() - (qd * A.translation());

  const double n = v.norm();
  if (n == 0.0) {
    b_ = 0.0;
    const double on = o.norm();
    s_ = on > 0.0 ? Eigen::Vector3d(o / on) : Eigen::Vector3d::UnitZ();
    d_ = on;
    o_perp_.setZero();
    p_.setZero();
    return;
  }
  s_ = v / n;
  b_ = 2.0 * std::atan2(n, w);
  d_ = o.dot(s_);
  o_perp_ = o - d_ * s_;
  // (I − R) p = o⊥ with p ⟂ s: in the plane ⟂ s, p = o⊥ / (1 − e^{ib})
  //   = (o⊥ + cot(b/2) s × o⊥) / 2.
  const double half = 0.5 * b_;
  p_ = 0.5 * (o_perp_ + (std::cos(half) / std::sin(half)) * s_.cross(o_perp_));
}

Eigen::Quaterniond ScrewMotion::relative_rotation(double t) const {
  const double h = 0.5 * t * b_;
  const double sh = std::sin(h);
  return Eigen::Quaterniond(std::cos(h), sh * s_.x(), sh * s_.y(), sh * s_.z());
}

Eigen::Isometry3d ScrewMotion::relative_at(double t) const {
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.linear() = relative_rotation(t).toRotationMatrix();
  // τ(t) = t d s + (1 − e^{itb})/(1 − e^{ib}) o⊥, and
  // (1 − e^{itb})/(1 − e^{ib}) = e^{i(t−1)b/2} sin(tb/2)/sin(b/2).
  const double half = 0.5 * b_;
  const double ratio = detail::sin_ratio(t, half);
  const double alpha = (t - 1.0) * half;
  const Eigen::Vector3d turned = std::cos(alpha) * o_perp_ + std::sin(alpha) * s_.cross(o_perp_);
  D.translation() = t * d_ * s_ + ratio * turned;
  return D;
}

Eigen::Isometry3d ScrewMotion::at(double t) const { return relative_at(t) * A_; }

}  // namespace reconfig::motion
