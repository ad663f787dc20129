#pragma once
/// @file
/// The path of a tool during one stroke: a translation, a uniform scaling or a rotation — the
/// relative transformation M of Sweepers §3–4, with its fractions α ⊙ M and its logarithm.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "reconfig/sculpt/tool.h"

namespace reconfig::sculpt {

/// One simple relative transformation M. Its fraction α ⊙ M = exp(α log M) is, for
/// - a translation by d: the translation by αd;
/// - a scaling by σ about c: the scaling by σ^α about c;
/// - a rotation by θ about the axis a through r: the rotation by αθ about the same axis.
struct ToolMotion {
  enum class Kind { kTranslation, kScale, kRotation };
  Kind kind = Kind::kTranslation;
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();  ///< translation d, or unit rotation axis a
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< scaling center c, or a point r on the axis
  double amount = 0;                                 ///< scaling factor σ (> 0), or angle θ (radians)

  static ToolMotion translation(const Eigen::Vector3d& d);
  /// @param factor  σ > 0
  static ToolMotion scaling(double factor, const Eigen::Vector3d& center);
  /// @param axis  rotation axis (non-zero; normalized here), @param radians θ (right hand rule)
  static ToolMotion rotation(const Eigen::Vector3d& axis, double radians, const Eigen::Vector3d& center);

  /// α ⊙ M as a motion of its own (one sub-step of a stroke: α = 1/s).
  ToolMotion fraction(double alpha) const;
  /// M⁻¹: the stroke that undoes this one.
  ToolMotion inverse() const;

  /// (α ⊙ M) p.
  Eigen::Vector3d apply(const Eigen::Vector3d& p, double alpha) const;
  /// ∂/∂x of (α ⊙ M) x: the linear part, σ^α I or the rotation by αθ (the identity for translations).
  Eigen::Matrix3d linear(double alpha) const;
  /// ∂/∂α of (α ⊙ M) p: log M applied to the moved point (log M)·[(α ⊙ M)p; 1].
  Eigen::Vector3d velocity(const Eigen::Vector3d& p, double alpha) const;
  /// The tool pose moved by α ⊙ M.
  ToolPose apply(const ToolPose& pose, double alpha) const;
  /// log M as a 4×4 matrix acting on homogeneous points (last row zero).
  Eigen::Matrix4d log_matrix() const;
};

}  // namespace reconfig::sculpt
