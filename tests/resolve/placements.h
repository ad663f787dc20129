#pragma once
/// @file
/// Rigid placements for the resolve tests: given, moved along a twist, or random.

#include <Eigen/Geometry>

#include <random>

namespace reconfig::resolve::testing {

inline Eigen::Isometry3d place(const Eigen::Vector3d& t, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  M.linear() = q.toRotationMatrix();
  M.translation() = t;
  return M;
}

/// The placement moved by the rigid motion (v, ω) about the world origin for a time h.
inline Eigen::Isometry3d moved(const Eigen::Isometry3d& p, const Eigen::Vector3d& v, const Eigen::Vector3d& w, double h) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  if (w.norm() > 0) m.linear() = Eigen::AngleAxisd(h * w.norm(), w.normalized()).toRotationMatrix();
  m.translation() = h * v;
  return m * p;
}

/// Random vectors, rotations and placements from one seed.
class RandomPlacements {
 public:
  explicit RandomPlacements(unsigned seed) : random_(seed) {}
  Eigen::Vector3d vector() { return {normal_(random_), normal_(random_), normal_(random_)}; }
  Eigen::Quaterniond rotation() {
    return Eigen::Quaterniond(normal_(random_), normal_(random_), normal_(random_), normal_(random_)).normalized();
  }
  /// Turned at random, moved from the origin by about `spread` (normal coordinates).
  Eigen::Isometry3d near_origin(double spread) {
    const Eigen::Vector3d t = spread * vector();
    return place(t, rotation());
  }

 private:
  std::mt19937 random_;
  std::normal_distribution<double> normal_{0, 1};
};

}  // namespace reconfig::resolve::testing
