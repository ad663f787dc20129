#include "reconfig/linkage/state_derivatives.h"

namespace reconfig::linkage {

void StateDerivatives::set_layout(const std::vector<std::vector<int>>& deps) {
  deps_ = deps;
  offset_.assign(deps.size() + 1, 0);
  for (std::size_t k = 0; k < deps.size(); ++k) offset_[k + 1] = offset_[k] + static_cast<int>(deps[k].size());
  blocks_.assign(offset_.back(), Eigen::Matrix2d::Zero());
}

Eigen::MatrixXd StateDerivatives::dense() const {
  const Eigen::Index n = static_cast<Eigen::Index>(deps_.size());
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (std::size_t k = 0; k < deps_.size(); ++k)
    for (std::size_t m = 0; m < deps_[k].size(); ++m)
      result.block<2, 2>(2 * static_cast<Eigen::Index>(k), 2 * deps_[k][m]) = blocks_[offset_[k] + m];
  return result;
}

void StateDerivatives::pull_back(const Eigen::Matrix2Xd& G, Eigen::Matrix2Xd& out) const {
  for (std::size_t k = 0; k < deps_.size(); ++k) {
    const Eigen::Vector2d g = G.col(static_cast<Eigen::Index>(k));
    if (g.x() == 0 && g.y() == 0) continue;
    for (std::size_t m = 0; m < deps_[k].size(); ++m) out.col(deps_[k][m]) += blocks_[offset_[k] + m].transpose() * g;
  }
}

}  // namespace reconfig::linkage
