#include "reconfig/motion/pose_derivatives.h"

#include "motion/detail/key_times.h"
#include "motion/detail/so3.h"

namespace reconfig::motion {

using detail::KeyLocation;

std::vector<TranslationKeyJacobian> translation_jacobian(const BezierTranslationTrack& track,
                                                         double t) {
  const KeyLocation loc = detail::locate(track.key_times(), t);
  std::vector<TranslationKeyJacobian> out;
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  if (loc.region != KeyLocation::Region::kInside) {
    TranslationKeyJacobian J;
    J.key = loc.segment;
    J.jacobian.block<3, 3>(0, 3) = I;  // x = t_key
    out.push_back(J);
    return out;
  }
  const std::size_t j = loc.segment;
  const double f = loc.f, g = 1.0 - f;
  const double dt = track.keys()[j + 1].time - track.keys()[j].time;
  const auto P = track.control_points(j);
  // eq. 18: ∂x/∂f
  const Eigen::Vector3d dxdf =
      3.0 * g * g * (P[1] - P[0]) + 6.0 * g * f * (P[2] - P[1]) + 3.0 * f * f * (P[3] - P[2]);

  TranslationKeyJacobian left;  // key j: t_j, w_j, s_j
  left.key = j;
  left.jacobian.block<3, 3>(0, 3) = g * g * g * I;        // eq. 19
  left.jacobian.block<3, 3>(0, 6) = 3.0 * g * g * f * I;  // eq. 20
  left.jacobian.col(9) = dxdf * ((f - 1.0) / dt);         // eq. 21–22: ∂f/∂s_j = (f − 1)/Δ

  TranslationKeyJacobian right;  // key j+1: u_{j+1}, t_{j+1}, s_{j+1}
  right.key = j + 1;
  right.jacobian.block<3, 3>(0, 0) = 3.0 * g * f * f * I;
  right.jacobian.block<3, 3>(0, 3) = f * f * f * I;
  right.jacobian.col(9) = dxdf * (-f / dt);  // ∂f/∂s_{j+1} = −f/Δ
  out.push_back(left);
  out.push_back(right);
  return out;
}

std::vector<RotationKeyJacobian> rotation_jacobian(const SlerpRotationTrack& track,
                                                   const Eigen::Vector3d& offset, double t) {
  const KeyLocation loc = detail::locate(track.key_times(), t);
  const Eigen::Vector3d r = track.evaluate(t) * offset;  // R(t)(p − c)
  const Eigen::Matrix3d minus_r_hat = -detail::hat(r);     // δ ↦ δ × r
  std::vector<RotationKeyJacobian> out;
  if (loc.region != KeyLocation::Region::kInside) {
    RotationKeyJacobian J;
    J.key = loc.segment;
    J.jacobian.leftCols<3>() = minus_r_hat;
    out.push_back(J);
    return out;
  }
  const std::size_t j = loc.segment;
  const double g = loc.f;
  const double dt = track.keys()[j + 1].time - track.keys()[j].time;
  const Eigen::Quaterniond& qa = track.keys()[j].rotation;
  // World-frame rotation vector of D = R_b R_aᵀ, so that R(g) = exp(g φ) R_a.
  const Eigen::Vector3d phi = qa * track.segment_rotation_vector(j);
  const Eigen::Matrix3d D = detail::quat_exp(phi).toRotationMatrix();
  const Eigen::Matrix3d Eg = detail::quat_exp(g * phi).toRotationMatrix();
  // Perturbing R_b by exp(δ): φ ↦ φ + J_l⁻¹(φ) δ, and exp(g(φ + ε)) ≈ exp(g J_l(gφ) ε) exp(gφ).
  const Eigen::Matrix3d K = g * detail::left_jacobian(g * phi) * detail::left_jacobian_inverse(phi);
  const Eigen::Matrix3d omega_b = K;
  // Perturbing R_a by exp(δ): D ↦ exp(−D δ) D and R(g) gets the extra factor exp(δ) R_a.
  const Eigen::Matrix3d omega_a = Eg - K * D;
  const Eigen::Vector3d dvdg = phi.cross(r);  // eq. 29 in world form: dR/dg = [φ]× R

  RotationKeyJacobian left;
  left.key = j;
  left.jacobian.leftCols<3>() = minus_r_hat * omega_a;
  left.jacobian.col(3) = dvdg * ((g - 1.0) / dt);
  RotationKeyJacobian right;
  right.key = j + 1;
  right.jacobian.leftCols<3>() = minus_r_hat * omega_b;
  right.jacobian.col(3) = dvdg * (-g / dt);
  out.push_back(left);
  out.push_back(right);
  return out;
}

KeyframeJacobian keyframe_jacobian(const BezierTranslationTrack& translation,
                                   const SlerpRotationTrack& rotation,
                                   const Eigen::Vector3d& center,
                                   const Eigen::Vector3d& rest_point, double t) {
  KeyframeJacobian J;
  J.rest_point = rotation.evaluate(t).toRotationMatrix();
  J.translation = translation_jacobian(translation, t);
  J.rotation = rotation_jacobian(rotation, rest_point - center, t);
  return J;
}

}  // namespace reconfig::motion
