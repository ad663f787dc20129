#include "linkage/detail/newton_block.h"

#include <algorithm>

namespace reconfig::linkage::detail {

RigidCoordinates rigid_coordinates(const Eigen::Vector2d& xi, const Eigen::Vector2d& xj, const Eigen::Vector2d& xk) {
  const Eigen::Vector2d d = xj - xi, e = xk - xi;
  const double n = d.squaredNorm();
  RigidCoordinates c;
  c.a = e.dot(d) / n;
  c.b = cross(d, e) / n;
  // a = e·d / n, b = cross(d, e) / n; ∂/∂e and ∂/∂d, then chain to x̄_i, x̄_j, x̄_k.
  const Eigen::Vector2d da_de = d / n, da_dd = (e - 2 * c.a * d) / n;
  const Eigen::Vector2d db_de = perp(d) / n, db_dd = (-perp(e) - 2 * c.b * d) / n;
  c.da_dk = da_de;
  c.da_dj = da_dd;
  c.da_di = -(da_de + da_dd);
  c.db_dk = db_de;
  c.db_dj = db_dd;
  c.db_di = -(db_de + db_dd);
  return c;
}

BlockSystem::BlockSystem(const NewtonBlock& block, const Eigen::Matrix2Xd& X0) : block_(&block) {
  involved_ = block.joints;
  auto add = [&](int joint) {
    if (std::find(involved_.begin(), involved_.end(), joint) == involved_.end()) involved_.push_back(joint);
  };
  for (const auto& link : block.links) {
    add(link.r0);
    add(link.r1);
    for (int m : link.others) add(m);
    const Eigen::Vector2d d = X0.col(link.r1) - X0.col(link.r0);
    d0_.push_back(d);
    length2_.push_back(d.squaredNorm());
    std::vector<RigidCoordinates> coordinates;
    for (int m : link.others) coordinates.push_back(rigid_coordinates(X0.col(link.r0), X0.col(link.r1), X0.col(m)));
    rigid_.push_back(coordinates);
    equations_ += 1 + 2 * static_cast<int>(link.others.size());
  }
}

int BlockSystem::column(int joint) const {
  return 2 * static_cast<int>(std::find(involved_.begin(), involved_.end(), joint) - involved_.begin());
}

void BlockSystem::evaluate(const Eigen::Matrix2Xd& X, Eigen::VectorXd& r, Eigen::MatrixXd* J) const {
  r.resize(equations_);
  if (J) J->setZero(equations_, 2 * static_cast<Eigen::Index>(involved_.size()));
  const Eigen::Matrix2d P = perp_matrix(), I = Eigen::Matrix2d::Identity();
  int row = 0;
  for (std::size_t l = 0; l < block_->links.size(); ++l) {
    const auto& link = block_->links[l];
    const Eigen::Vector2d d = X.col(link.r1) - X.col(link.r0);
    r[row] = d.squaredNorm() - length2_[l];
    if (J) {
      J->block<1, 2>(row, column(link.r1)) += 2 * d.transpose();
      J->block<1, 2>(row, column(link.r0)) -= 2 * d.transpose();
    }
    ++row;
    for (std::size_t o = 0; o < link.others.size(); ++o) {
      const RigidCoordinates& c = rigid_[l][o];
      const Eigen::Matrix2d A = c.a * I + c.b * P;
      r.segment<2>(row) = X.col(link.others[o]) - X.col(link.r0) - A * d;
      if (J) {
        J->block<2, 2>(row, column(link.others[o])) += I;
        J->block<2, 2>(row, column(link.r1)) -= A;
        J->block<2, 2>(row, column(link.r0)) += A - I;
      }
      row += 2;
    }
  }
}

Eigen::MatrixXd BlockSystem::parameter_jacobian(const Eigen::Matrix2Xd& X) const {
  Eigen::MatrixXd Jp = Eigen::MatrixXd::Zero(equations_, 2 * static_cast<Eigen::Index>(involved_.size()));
  int row = 0;
  for (std::size_t l = 0; l < block_->links.size(); ++l) {
    const auto& link = block_->links[l];
    const Eigen::Vector2d d = X.col(link.r1) - X.col(link.r0);
    Jp.block<1, 2>(row, column(link.r1)) -= 2 * d0_[l].transpose();
    Jp.block<1, 2>(row, column(link.r0)) += 2 * d0_[l].transpose();
    ++row;
    const Eigen::Vector2d pd = perp(d);
    for (std::size_t o = 0; o < link.others.size(); ++o) {
      const RigidCoordinates& c = rigid_[l][o];
      // r = x_m − x_r0 − a d − b ⟂d: ∂r/∂x̄ = −d ⊗ ∂a/∂x̄ − ⟂d ⊗ ∂b/∂x̄.
      Jp.block<2, 2>(row, column(link.r0)) -= d * c.da_di.transpose() + pd * c.db_di.transpose();
      Jp.block<2, 2>(row, column(link.r1)) -= d * c.da_dj.transpose() + pd * c.db_dj.transpose();
      Jp.block<2, 2>(row, column(link.others[o])) -= d * c.da_dk.transpose() + pd * c.db_dk.transpose();
      row += 2;
    }
  }
  return Jp;
}

}  // namespace reconfig::linkage::detail
