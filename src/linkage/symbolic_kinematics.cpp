#include "reconfig/linkage/symbolic_kinematics.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "linkage/detail/newton_block.h"
#include "reconfig/common/input_error.h"

namespace reconfig::linkage {
namespace {

using detail::cross;
using detail::perp;

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

// Position of `value` in the sorted list `list` (it must be there).
int position_in(const std::vector<int>& list, int value) {
  return static_cast<int>(std::lower_bound(list.begin(), list.end(), value) - list.begin());
}

void merge_into(std::vector<int>& target, const std::vector<int>& source) {
  std::vector<int> merged;
  std::set_union(target.begin(), target.end(), source.begin(), source.end(), std::back_inserter(merged));
  target.swap(merged);
}

}  // namespace

SymbolicKinematics::SymbolicKinematics(const Linkage& linkage, JointOrder order)
    : linkage_(linkage), order_(std::move(order)) {
  for (std::size_t r = 0; r < order_.rules.size(); ++r)
    if (order_.rules[r].kind == RuleKind::kTriangle) triangle_rules_.push_back(static_cast<int>(r));
  std::string error;
  int joint = -1;
  if (!compute_constants(linkage_.initial_positions(), constants_, &error, &joint))
    throw InputError("", "joints[" + std::to_string(joint) + "]", error);
  X0_ = linkage_.initial_positions();
  angle0_ = linkage_.initial_motor_angle();
  build_dependencies();
  for (const NewtonBlock& block : order_.blocks)
    block_guess_.emplace_back(2, static_cast<Eigen::Index>(block.joints.size()));
  reset_continuation();
}

bool SymbolicKinematics::compute_constants(const Eigen::Matrix2Xd& X0, std::vector<Constants>& constants,
                                           std::string* error, int* joint) const {
  constants.assign(order_.rules.size(), Constants{});
  for (std::size_t r = 0; r < order_.rules.size(); ++r) {
    const Rule& rule = order_.rules[r];
    Constants& c = constants[r];
    switch (rule.kind) {
      case RuleKind::kFixed:
      case RuleKind::kNewtonBlock: break;
      case RuleKind::kMotor: c.A = (X0.col(rule.k) - X0.col(rule.i)).norm(); break;
      case RuleKind::kTriangle: {
        c.e_ik = X0.col(rule.k) - X0.col(rule.i);
        c.e_jk = X0.col(rule.k) - X0.col(rule.j);
        c.A = c.e_ik.squaredNorm();
        c.B = c.e_jk.squaredNorm();
        const Eigen::Vector2d d = X0.col(rule.j) - X0.col(rule.i);
        const double orientation = cross(d, c.e_ik);
        // sin of the angle at k: |e_ik × e_jk| / (|e_ik| |e_jk|).
        const double sine = std::abs(cross(c.e_ik, c.e_jk)) / std::sqrt(c.A * c.B);
        if (!(sine > 1e-9) || d.squaredNorm() == 0) {
          if (error)
            *error = "joint \"" + linkage_.joints[rule.k].name + "\" is singular in the initial configuration: " +
                     describe_rule(linkage_, order_, rule) + " is a degenerate (collinear) triangle";
          if (joint) *joint = rule.k;
          return false;
        }
        c.sign = orientation > 0 ? 1.0 : -1.0;
        break;
      }
      case RuleKind::kRigid: {
        const detail::RigidCoordinates rc = detail::rigid_coordinates(X0.col(rule.i), X0.col(rule.j), X0.col(rule.k));
        c.a = rc.a, c.b = rc.b;
        c.da_di = rc.da_di, c.da_dj = rc.da_dj, c.da_dk = rc.da_dk;
        c.db_di = rc.db_di, c.db_dj = rc.db_dj, c.db_dk = rc.db_dk;
        break;
      }
    }
  }
  return true;
}

bool SymbolicKinematics::set_initial_positions(const Eigen::Matrix2Xd& X0) {
  std::vector<Constants> constants;
  if (!compute_constants(X0, constants, nullptr, nullptr)) return false;
  constants_.swap(constants);
  X0_ = X0;
  linkage_.set_initial_positions(X0);
  angle0_ = linkage_.initial_motor_angle();
  reset_continuation();
  return true;
}

void SymbolicKinematics::reset_continuation() const {
  for (std::size_t b = 0; b < order_.blocks.size(); ++b)
    for (std::size_t m = 0; m < order_.blocks[b].joints.size(); ++m)
      block_guess_[b].col(static_cast<Eigen::Index>(m)) = X0_.col(order_.blocks[b].joints[m]);
  guess_angle_ = angle0_;
}

void SymbolicKinematics::build_dependencies() {
  const std::size_t n = linkage_.joints.size();
  std::vector<std::vector<int>> deps(n);
  maps_.assign(order_.rules.size(), RuleMaps{});
  for (std::size_t r = 0; r < order_.rules.size(); ++r) {
    const Rule& rule = order_.rules[r];
    if (rule.kind == RuleKind::kNewtonBlock) {
      const NewtonBlock& block = order_.blocks[rule.block];
      detail::BlockSystem system(block, X0_);
      std::vector<int> all;
      for (int z : system.involved()) {
        merge_into(all, {z});
        if (std::find(block.joints.begin(), block.joints.end(), z) == block.joints.end()) merge_into(all, deps[z]);
      }
      for (int k : block.joints) deps[k] = all;
      continue;
    }
    std::vector<int>& out = deps[rule.k];
    out = {rule.k};
    if (rule.i >= 0) merge_into(out, deps[rule.i]), merge_into(out, {rule.i});
    if (rule.j >= 0) merge_into(out, deps[rule.j]), merge_into(out, {rule.j});
    RuleMaps& map = maps_[r];
    if (rule.i >= 0) {
      for (int p : deps[rule.i]) map.from_i.push_back(position_in(out, p));
      map.pos_i = position_in(out, rule.i);
    }
    if (rule.j >= 0) {
      for (int p : deps[rule.j]) map.from_j.push_back(position_in(out, p));
      map.pos_j = position_in(out, rule.j);
    }
    map.pos_k = position_in(out, rule.k);
  }
  layout_.set_layout(deps);
}

bool SymbolicKinematics::solve(double angle, Eigen::Matrix2Xd& X, ReconstructionFailure* failure) const {
  return solve_continued(angle, X, nullptr, nullptr, failure);
}

bool SymbolicKinematics::solve(double angle, Eigen::Matrix2Xd& X, StateDerivatives& D,
                               ReconstructionFailure* failure) const {
  return solve_continued(angle, X, &D, nullptr, failure);
}

bool SymbolicKinematics::solve(double angle, Eigen::Matrix2Xd& X, StateTape& tape, ReconstructionFailure* failure) const {
  return solve_continued(angle, X, nullptr, &tape, failure);
}

bool SymbolicKinematics::solve_continued(double angle, Eigen::Matrix2Xd& X, StateDerivatives* derivatives,
                                         StateTape* tape, ReconstructionFailure* failure) const {
  if (order_.blocks.empty()) return solve_once(angle, X, derivatives, tape, failure);
  // Newton blocks: continue from the last solution in steps of at most 3°.
  const double kStep = 3 * std::numbers::pi / 180;
  double from = guess_angle_;
  const double delta = angle - from;  // unwrapped: the caller chooses the way round
  const int steps = static_cast<int>(std::ceil(std::abs(delta) / kStep));
  for (int s = 1; s < steps; ++s)
    if (!solve_once(from + delta * s / steps, X, nullptr, nullptr, failure)) return false;
  return solve_once(angle, X, derivatives, tape, failure);
}

bool SymbolicKinematics::solve_once(double angle, Eigen::Matrix2Xd& X, StateDerivatives* D, StateTape* tape,
                                    ReconstructionFailure* failure) const {
  X.resize(2, static_cast<Eigen::Index>(linkage_.joints.size()));
  if (D && D->joint_count() != joint_count()) *D = layout_;
  if (tape) tape->steps.resize(order_.rules.size()), tape->blocks.resize(order_.blocks.size());
  const bool derivatives = D || tape;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity(), P = detail::perp_matrix();
  const double cosine = std::cos(angle), sine = std::sin(angle);
  for (std::size_t r = 0; r < order_.rules.size(); ++r) {
    const Rule& rule = order_.rules[r];
    const Constants& c = constants_[r];
    Eigen::Matrix2d Mi = Eigen::Matrix2d::Zero(), Mj = Eigen::Matrix2d::Zero();  // ∂x_k/∂x_i, ∂x_k/∂x_j
    Eigen::Matrix2d Pi = Eigen::Matrix2d::Zero(), Pj = Eigen::Matrix2d::Zero(), Pk = Eigen::Matrix2d::Zero();  // ∂x_k/∂x̄
    switch (rule.kind) {
      case RuleKind::kFixed:
        X.col(rule.k) = X0_.col(rule.k);
        if (D) D->block(rule.k, 0) = I;
        if (tape) tape->steps[r] = {rule.k, -1, -1, -1, Mi, Mj, Pi, Pj, I};
        continue;
      case RuleKind::kNewtonBlock:
        if (!solve_block(static_cast<int>(r), X, D, tape, failure)) return false;
        continue;
      case RuleKind::kMotor: {
        const Eigen::Vector2d u(cosine, sine);
        X.col(rule.k) = X.col(rule.i) + c.A * u;
        if (!derivatives) continue;
        const Eigen::Vector2d e = (X0_.col(rule.k) - X0_.col(rule.i)) / c.A;
        Mi = I;
        Mj.setZero();
        Pk = u * e.transpose();
        Pi = -Pk;
        Pj.setZero();
        break;
      }
      case RuleKind::kRigid: {
        const Eigen::Vector2d d = X.col(rule.j) - X.col(rule.i);
        const Eigen::Vector2d pd = perp(d);
        X.col(rule.k) = X.col(rule.i) + c.a * d + c.b * pd;
        if (!derivatives) continue;
        Mj = c.a * I + c.b * P;
        Mi = I - Mj;
        Pi = d * c.da_di.transpose() + pd * c.db_di.transpose();
        Pj = d * c.da_dj.transpose() + pd * c.db_dj.transpose();
        Pk = d * c.da_dk.transpose() + pd * c.db_dk.transpose();
        break;
      }
      case RuleKind::kTriangle: {
        const Eigen::Vector2d d = X.col(rule.j) - X.col(rule.i);
        const double D2 = d.squaredNorm();
        const double p = 0.5 + (c.A - c.B) / (2 * D2);
        const double t = c.A / D2 - p * p;  // (h / |d|)², h: height of k over the line i–j
        if (!(t >= 0) || D2 == 0) {
          if (failure) {
            const double length = std::sqrt(D2), lik = std::sqrt(c.A), ljk = std::sqrt(c.B);
            failure->kind = ReconstructionFailure::Kind::kCannotClose;
            failure->rule = static_cast<int>(r);
            failure->joint = rule.k;
            failure->message = "joint \"" + linkage_.joints[rule.k].name + "\" cannot be reconstructed: triangle " +
                               describe_rule(linkage_, order_, rule) + " cannot close (distance " +
                               format_number(length) + (length > lik + ljk ? " > " : " < ") +
                               format_number(length > lik + ljk ? lik + ljk : std::abs(lik - ljk)) + ")";
          }
          return false;
        }
        const double q = c.sign * std::sqrt(t);
        const Eigen::Vector2d pd = perp(d);
        X.col(rule.k) = X.col(rule.i) + p * d + q * pd;
        if (!derivatives) continue;
        const Eigen::Vector2d dp_dd = -(c.A - c.B) / (D2 * D2) * d;
        const Eigen::Vector2d dt_dd = -2 * c.A / (D2 * D2) * d - 2 * p * dp_dd;
        const Eigen::Vector2d dq_dd = dt_dd / (2 * q);
        Mj = p * I + q * P + d * dp_dd.transpose() + pd * dq_dd.transpose();
        Mi = I - Mj;
        const Eigen::Vector2d gA = d / (2 * D2) + pd * ((1 - p) / D2 / (2 * q));
        const Eigen::Vector2d gB = -d / (2 * D2) + pd * (p / D2 / (2 * q));
        Pk = 2 * (gA * c.e_ik.transpose() + gB * c.e_jk.transpose());
        Pi = -2 * gA * c.e_ik.transpose();
        Pj = -2 * gB * c.e_jk.transpose();
        break;
      }
    }
    if (tape) tape->steps[r] = {rule.k, rule.i, rule.j, -1, Mi, Mj, Pi, Pj, Pk};
    if (!D) continue;
    // Chain rule: ∂x_k/∂x̄ = Mi ∂x_i/∂x̄ + Mj ∂x_j/∂x̄ + direct terms.
    const RuleMaps& map = maps_[r];
    Eigen::Matrix2d* out = D->blocks(rule.k);
    const std::size_t count = D->dependencies(rule.k).size();
    for (std::size_t m = 0; m < count; ++m) out[m].setZero();
    const Eigen::Matrix2d* in_i = D->blocks(rule.i);
    for (std::size_t m = 0; m < map.from_i.size(); ++m) out[map.from_i[m]].noalias() += Mi * in_i[m];
    if (rule.j >= 0) {
      const Eigen::Matrix2d* in_j = D->blocks(rule.j);
      for (std::size_t m = 0; m < map.from_j.size(); ++m) out[map.from_j[m]].noalias() += Mj * in_j[m];
      out[map.pos_j] += Pj;
    }
    out[map.pos_i] += Pi;
    out[map.pos_k] += Pk;
  }
  if (!order_.blocks.empty()) guess_angle_ = angle;
  return true;
}

bool SymbolicKinematics::solve_block(int rule_index, Eigen::Matrix2Xd& X, StateDerivatives* D, StateTape* tape,
                                     ReconstructionFailure* failure) const {
  const Rule& rule = order_.rules[rule_index];
  const NewtonBlock& block = order_.blocks[rule.block];
  const detail::BlockSystem system(block, X0_);
  Eigen::Matrix2Xd& guess = block_guess_[rule.block];
  for (std::size_t b = 0; b < block.joints.size(); ++b) X.col(block.joints[b]) = guess.col(static_cast<Eigen::Index>(b));
  const int n = system.unknowns();
  double scale = 1;
  for (int z : system.involved()) scale = std::max(scale, X0_.col(z).cwiseAbs().maxCoeff());
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  bool converged = false;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  for (int iteration = 0; iteration < 50; ++iteration) {
    system.evaluate(X, r, &J);
    if (r.lpNorm<Eigen::Infinity>() <= 1e-13 * scale * scale) {
      converged = true;
      break;
    }
    lu.compute(J.leftCols(n));
    const Eigen::VectorXd step = lu.solve(-r);
    if (!step.allFinite()) break;
    for (std::size_t b = 0; b < block.joints.size(); ++b) X.col(block.joints[b]) += step.segment<2>(2 * static_cast<Eigen::Index>(b));
  }
  if (converged) {
    system.evaluate(X, r, &J);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J.leftCols(n));
    const auto& s = svd.singularValues();
    converged = s(s.size() - 1) > 1e-8 * std::max(1.0, s(0));
  }
  if (!converged) {
    if (failure) {
      std::string names;
      for (int k : block.joints) names += (names.empty() ? "\"" : ", \"") + linkage_.joints[k].name + "\"";
      failure->kind = ReconstructionFailure::Kind::kNewtonFailed;
      failure->rule = rule_index;
      failure->joint = block.joints.front();
      failure->message = "joints " + names + " (complex loop) cannot be reconstructed: the Newton solve " +
                         "did not converge to a regular configuration";
    }
    return false;
  }
  for (std::size_t b = 0; b < block.joints.size(); ++b) guess.col(static_cast<Eigen::Index>(b)) = X.col(block.joints[b]);
  if (!D && !tape) return true;
  // Implicit function theorem: J_y dy + J_z dz + J_p dx̄ = 0.
  const std::vector<int>& involved = system.involved();
  if (tape) {
    StateTape::Step& step = tape->steps[rule_index];
    step = {};
    step.block = rule.block;
    StateTape::Block& record = tape->blocks[rule.block];
    record.outputs = block.joints;
    record.inputs.assign(involved.begin() + n / 2, involved.end());
    record.params = involved;
    lu.compute(J.leftCols(n));
    record.S_in = -lu.solve(J.rightCols(J.cols() - n));
    record.S_param = -lu.solve(system.parameter_jacobian(X));
    if (!D) return true;
  }
  const std::vector<int>& all = D->dependencies(block.joints.front());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2 * static_cast<Eigen::Index>(all.size()));
  const Eigen::MatrixXd Jp = system.parameter_jacobian(X);
  for (std::size_t z = 0; z < involved.size(); ++z) {
    const Eigen::Index col = 2 * static_cast<Eigen::Index>(z);
    rhs.middleCols<2>(2 * position_in(all, involved[z])) += Jp.middleCols<2>(col);
    if (static_cast<int>(z) < n / 2) continue;  // block joint: no incoming chain
    const int joint = involved[z];
    const auto& deps = D->dependencies(joint);
    for (std::size_t m = 0; m < deps.size(); ++m)
      rhs.middleCols<2>(2 * position_in(all, deps[m])) += J.middleCols<2>(col) * D->block(joint, static_cast<int>(m));
  }
  const Eigen::MatrixXd dy = -lu.compute(J.leftCols(n)).solve(rhs);
  for (std::size_t b = 0; b < block.joints.size(); ++b)
    for (std::size_t m = 0; m < all.size(); ++m)
      D->block(block.joints[b], static_cast<int>(m)) =
          dy.block<2, 2>(2 * static_cast<Eigen::Index>(b), 2 * static_cast<Eigen::Index>(m));
  return true;
}

std::vector<double> SymbolicKinematics::singularity_distances(const Eigen::Matrix2Xd& X) const {
  std::vector<double> result;
  result.reserve(triangle_rules_.size());
  for (int r : triangle_rules_) {
    const Rule& rule = order_.rules[r];
    const Eigen::Vector2d u = X.col(rule.i) - X.col(rule.k), v = X.col(rule.j) - X.col(rule.k);
    const double s = cross(u, v);
    result.push_back(s * s / (u.squaredNorm() * v.squaredNorm()));
  }
  return result;
}

}  // namespace reconfig::linkage
