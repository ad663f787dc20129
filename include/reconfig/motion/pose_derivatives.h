#pragma once
/// @file
/// Derivatives of a moving point with respect to keyframe parameters (reconfigurables
/// paper, eq. 10–29), for hints and automatic resolution.

#include "reconfig/motion/bezier_translation_track.h"
#include "reconfig/motion/slerp_rotation_track.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace reconfig::motion {

/// ∂x(t)/∂(u_j, t_j, w_j, s_j) for one translation key j: a 3×10 block whose columns are
/// 0–2 the in handle u_j, 3–5 the point t_j, 6–8 the out handle w_j, 9 the time s_j.
/// Because v = R(p − c) + c + x, this is also ∂v/∂(key j) for every point p.
struct TranslationKeyJacobian {
  std::size_t key = 0;
  Eigen::Matrix<double, 3, 10> jacobian = Eigen::Matrix<double, 3, 10>::Zero();
};

/// ∂v(t)/∂(δ_j, σ_j) for one rotation key j: a 3×4 block whose columns are 0–2 a rotation
/// perturbation δ_j ∈ R³ of the key and 3 the time σ_j.
///
/// Parameterization of the rotation (documented choice): the key's rotation is perturbed in
/// the world frame, θ_j(δ) = exp(δ) θ_j, i.e. quaternion `q_j(δ) = (cos(|δ|/2),
/// sin(|δ|/2) δ/|δ|) q_j`, rotation matrix exp([δ]×) R_j; derivatives are taken at δ = 0.
/// A gizmo that turns the key by a small angle α about a world axis a changes v by
/// `jacobian.leftCols<3>() * (α a)`.
struct RotationKeyJacobian {
  std::size_t key = 0;
  Eigen::Matrix<double, 3, 4> jacobian = Eigen::Matrix<double, 3, 4>::Zero();
};

/// Everything that moves a point p of a keyframed part at time t.
struct KeyframeJacobian {
  /// ∂v/∂p = R(t) (eq. 10), 3×3.
  Eigen::Matrix3d rest_point = Eigen::Matrix3d::Identity();
  /// One block per translation key that influences x(t) (at most two), by increasing key.
  std::vector<TranslationKeyJacobian> translation;
  /// One block per rotation key that influences θ(t) (at most two), by increasing key.
  std::vector<RotationKeyJacobian> rotation;
};

/// ∂x(t)/∂(translation keys): the keys j, j+1 of the segment s_j <= t < s_{j+1}, or only
/// the first/last key's point outside the track (clamped: there the key time has no
/// influence), or the single key. At a key time the right-hand segment is used (the
/// derivative with respect to that key's time is one-sided there).
/// @param track  the translation track
/// @param t      time
std::vector<TranslationKeyJacobian> translation_jacobian(const BezierTranslationTrack& track,
                                                         double t);

/// ∂v(t)/∂(rotation keys) for the point whose offset from the center is `offset` = p − c
/// (#3). Same segment conventions as `translation_jacobian`. Not differentiable where a
/// segment turns by exactly π (the shortest arc flips there); finite and continuous
/// everywhere else, including identical keys.
/// @param track   the rotation track
/// @param offset  p − c, rest-pose point relative to the part's center (#3)
/// @param t       time
std::vector<RotationKeyJacobian> rotation_jacobian(const SlerpRotationTrack& track,
                                                   const Eigen::Vector3d& offset, double t);

/// All derivatives of `v(t) = R(t)(p − c) + c + x(t)` (eq. 9).
/// @param translation  translation track x
/// @param rotation     rotation track R
/// @param center       the part's center of mass c (#3)
/// @param rest_point   the rest-pose point p (#3)
/// @param t            time
KeyframeJacobian keyframe_jacobian(const BezierTranslationTrack& translation,
                                   const SlerpRotationTrack& rotation,
                                   const Eigen::Vector3d& center,
                                   const Eigen::Vector3d& rest_point, double t);

}  // namespace reconfig::motion
