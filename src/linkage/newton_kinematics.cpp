#include "reconfig/linkage/newton_kinematics.h"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <numbers>

namespace reconfig::linkage {

NewtonKinematics::NewtonKinematics(const Linkage& linkage) : linkage_(linkage) {
  const auto& links = linkage.links;
  joint_slot_.assign(linkage.joints.size(), {-1, -1});
  state_.resize(3 * static_cast<Eigen::Index>(links.size()));
  std::vector<std::vector<std::pair<int, int>>> carriers(linkage.joints.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    for (int j : links[l]) center += linkage.joints[j].position;
    center /= static_cast<double>(links[l].size());
    state_.segment<3>(3 * static_cast<Eigen::Index>(l)) << center.x(), center.y(), 0.0;
    std::vector<Eigen::Vector2d> offsets;
    for (std::size_t s = 0; s < links[l].size(); ++s) {
      const int j = links[l][s];
      offsets.push_back(linkage.joints[j].position - center);
      carriers[j].push_back({static_cast<int>(l), static_cast<int>(s)});
      scale_ = std::max(scale_, linkage.joints[j].position.cwiseAbs().maxCoeff());
    }
    local_.push_back(offsets);
  }
  for (std::size_t j = 0; j < linkage.joints.size(); ++j) {
    const auto& on = carriers[j];
    if (on.empty()) continue;
    joint_slot_[j] = on.front();
    if (linkage.joints[j].fixed) {
      for (const auto& [l, s] : on) pins_.push_back({l, s, -1, -1, linkage.joints[j].position});
    } else {
      for (std::size_t t = 1; t < on.size(); ++t) pins_.push_back({on[0].first, on[0].second, on[t].first, on[t].second, Eigen::Vector2d::Zero()});
    }
  }
  for (const auto& [l, s] : carriers[linkage.motor.joint]) {
    for (int j : links[l])
      if (j == linkage.motor.center) crank_ = l;
    if (crank_ >= 0) break;
  }
  angle0_ = linkage.initial_motor_angle();
  equations_ = 2 * static_cast<int>(pins_.size()) + 1;
}

void NewtonKinematics::reset() {
  for (std::size_t l = 0; l < linkage_.links.size(); ++l) {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    for (int j : linkage_.links[l]) center += linkage_.joints[j].position;
    center /= static_cast<double>(linkage_.links[l].size());
    state_.segment<3>(3 * static_cast<Eigen::Index>(l)) << center.x(), center.y(), 0.0;
  }
}

Eigen::Vector2d NewtonKinematics::world(int link, int slot) const {
  const double theta = state_[3 * link + 2];
  const double c = std::cos(theta), s = std::sin(theta);
  const Eigen::Vector2d& p = local_[link][slot];
  return Eigen::Vector2d(state_[3 * link] + c * p.x() - s * p.y(), state_[3 * link + 1] + s * p.x() + c * p.y());
}

void NewtonKinematics::residual(double angle, Eigen::VectorXd& r, Eigen::SparseMatrix<double>* J) const {
  r.resize(equations_);
  std::vector<Eigen::Triplet<double>> triplets;
  // d world(link, slot) / d θ = R'(θ) p = (−s p.x − c p.y, c p.x − s p.y)
  auto add_body = [&](int row, int link, int slot, double sign) {
    const double theta = state_[3 * link + 2];
    const double c = std::cos(theta), s = std::sin(theta);
    const Eigen::Vector2d& p = local_[link][slot];
    triplets.emplace_back(row, 3 * link, sign);
    triplets.emplace_back(row + 1, 3 * link + 1, sign);
    triplets.emplace_back(row, 3 * link + 2, sign * (-s * p.x() - c * p.y()));
    triplets.emplace_back(row + 1, 3 * link + 2, sign * (c * p.x() - s * p.y()));
  };
  int row = 0;
  for (const Pin& pin : pins_) {
    const Eigen::Vector2d a = world(pin.link_a, pin.slot_a);
    const Eigen::Vector2d b = pin.link_b < 0 ? pin.ground : world(pin.link_b, pin.slot_b);
    r.segment<2>(row) = a - b;
    if (J) {
      add_body(row, pin.link_a, pin.slot_a, 1);
      if (pin.link_b >= 0) add_body(row, pin.link_b, pin.slot_b, -1);
    }
    row += 2;
  }
  // Motor: the crank's rotation equals the motor value minus its initial value (unwrapped
  // to the current winding).
  const double theta = state_[3 * crank_ + 2];
  const double target = angle - angle0_;
  r[row] = std::remainder(theta - target, 2 * std::numbers::pi);
  if (J) {
    triplets.emplace_back(row, 3 * crank_ + 2, 1.0);
    J->resize(equations_, state_.size());
    J->setFromTriplets(triplets.begin(), triplets.end());
  }
}

bool NewtonKinematics::solve(double angle, Eigen::Matrix2Xd& X, int* iterations) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  bool converged = false, analyzed = false;
  int iteration = 0;
  for (; iteration < 50; ++iteration) {
    residual(angle, r, &J);
    if (r.lpNorm<Eigen::Infinity>() <= 1e-12 * scale_) {
      converged = true;
      break;
    }
    const Eigen::SparseMatrix<double> JtJ = J.transpose() * J;
    if (!analyzed) solver.analyzePattern(JtJ), analyzed = true;
    solver.factorize(JtJ);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd step = solver.solve(-(J.transpose() * r));
    if (!step.allFinite()) break;
    state_ += step;
  }
  if (iterations) *iterations = iteration;
  X.resize(2, static_cast<Eigen::Index>(linkage_.joints.size()));
  for (std::size_t j = 0; j < linkage_.joints.size(); ++j) {
    const auto [l, s] = joint_slot_[j];
    X.col(static_cast<Eigen::Index>(j)) = l < 0 ? linkage_.joints[j].position : world(l, s);
  }
  return converged;
}

}  // namespace reconfig::linkage
