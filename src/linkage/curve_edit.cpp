#include "reconfig/linkage/curve_edit.h"

#include <Eigen/Geometry>
#include <cassert>
#include <cmath>

namespace reconfig::linkage {

std::vector<Eigen::Vector2d> transform_curve(const std::vector<Eigen::Vector2d>& curve, double scale, double rotation,
                                             const Eigen::Vector2d& translation) {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const auto& p : curve) centroid += p;
  if (!curve.empty()) centroid /= static_cast<double>(curve.size());
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(rotation).toRotationMatrix();
  std::vector<Eigen::Vector2d> result;
  result.reserve(curve.size());
  for (const auto& p : curve) result.push_back(centroid + scale * (R * (p - centroid)) + translation);
  return result;
}

std::vector<Eigen::Vector2d> soft_drag_curve(const std::vector<Eigen::Vector2d>& curve, int index,
                                             const Eigen::Vector2d& displacement, double radius, bool closed) {
  assert(index >= 0 && index < static_cast<int>(curve.size()) && radius > 0);
  const int n = static_cast<int>(curve.size());
  // Arc length from the start to each point, and the total (closing segment included).
  std::vector<double> along(n, 0.0);
  for (int s = 1; s < n; ++s) along[s] = along[s - 1] + (curve[s] - curve[s - 1]).norm();
  const double total = along[n - 1] + (closed ? (curve.front() - curve.back()).norm() : 0.0);
  std::vector<Eigen::Vector2d> result = curve;
  for (int s = 0; s < n; ++s) {
    double distance = std::abs(along[s] - along[index]);
    if (closed) distance = std::min(distance, total - distance);
    const double w = s == index ? 1.0 : std::exp(-(distance / radius) * (distance / radius));
    result[s] += w * displacement;
  }
  return result;
}

}  // namespace reconfig::linkage
