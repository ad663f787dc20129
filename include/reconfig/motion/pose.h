#pragma once
/// @file
/// A rigid part's pose (reconfigurables paper, eq. 9).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace reconfig::motion {

/// Where a part is: a rotation about the part's center of mass c, then a translation x.
/// A rest-pose point p goes to `v = R (p − c) + c + x`.
struct Pose {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit quaternion R
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();          ///< x

  /// `R (p − center) + center + x`.
  Eigen::Vector3d apply(const Eigen::Vector3d& center, const Eigen::Vector3d& p) const;

  /// The same placement as a rigid map of space: `v = M p`.
  Eigen::Isometry3d to_isometry(const Eigen::Vector3d& center) const;

  /// The pose, about `center`, that places points as the rigid map `M` does.
  static Pose from_isometry(const Eigen::Isometry3d& M, const Eigen::Vector3d& center);

  /// The same numbers, bit for bit: the quaternions' coefficients as stored, so q and −q
  /// (the same rotation) differ. For "did an edit change this?", not for geometry.
  bool operator==(const Pose& other) const {
    return rotation.coeffs() == other.rotation.coeffs() && translation == other.translation;
  }
};

}  // namespace reconfig::motion
