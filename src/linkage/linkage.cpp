#include "reconfig/linkage/linkage.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace reconfig::linkage {

int Linkage::find_joint(const std::string& name) const {
  for (std::size_t j = 0; j < joints.size(); ++j)
    if (joints[j].name == name) return static_cast<int>(j);
  return -1;
}

Eigen::Matrix2Xd Linkage::initial_positions() const {
  Eigen::Matrix2Xd X(2, static_cast<Eigen::Index>(joints.size()));
  for (std::size_t j = 0; j < joints.size(); ++j) X.col(static_cast<Eigen::Index>(j)) = joints[j].position;
  return X;
}

void Linkage::set_initial_positions(const Eigen::Matrix2Xd& X) {
  assert(X.cols() == static_cast<Eigen::Index>(joints.size()));
  for (std::size_t j = 0; j < joints.size(); ++j) joints[j].position = X.col(static_cast<Eigen::Index>(j));
}

double Linkage::initial_motor_angle() const {
  assert(motor.center >= 0 && motor.joint >= 0);
  const Eigen::Vector2d r = joints[motor.joint].position - joints[motor.center].position;
  return std::atan2(r.y(), r.x());
}

std::vector<std::vector<int>> Linkage::links_of_joints() const {
  std::vector<std::vector<int>> result(joints.size());
  for (std::size_t l = 0; l < links.size(); ++l)
    for (int j : links[l]) result[j].push_back(static_cast<int>(l));
  return result;
}

std::vector<std::vector<int>> Linkage::neighbours() const {
  std::vector<std::vector<int>> result(joints.size());
  for (const auto& link : links)
    for (int a : link)
      for (int b : link)
        if (a != b) result[a].push_back(b);
  for (auto& list : result) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return result;
}

}  // namespace reconfig::linkage
