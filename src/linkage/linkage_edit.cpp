#include "reconfig/linkage/linkage_edit.h"

#include <LBFGS.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "linkage/detail/newton_block.h"
#include "reconfig/common/input_error.h"
#include "reconfig/linkage/motion_range.h"
#include "reconfig/linkage/symbolic_kinematics.h"

namespace reconfig::linkage {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Signs of the reconstruction triangles (i, j, k) in X0.
std::vector<double> orientations(const JointOrder& order, const Eigen::Matrix2Xd& X0) {
  std::vector<double> signs;
  for (const Rule& rule : order.rules)
    if (rule.kind == RuleKind::kTriangle)
      signs.push_back(detail::cross(X0.col(rule.j) - X0.col(rule.i), X0.col(rule.k) - X0.col(rule.i)));
  return signs;
}

class EditProblem {  // EditEnergy::Impl
 public:
  EditProblem(const Linkage& original, const EditObjectives& objectives, const EditSettings& settings)
      : objectives_(objectives),
        order_(order_joints(original)),
        kinematics_(original, order_),
        angles_(edit_sample_angles(original, settings.samples)),
        pairs_(link_pairs(original)),
        references_(objectives.reference_lengths.empty() ? link_lengths(original) : objectives.reference_lengths),
        signs_(orientations(order_, original.initial_positions())) {
    if (references_.size() != pairs_.size()) throw std::invalid_argument("reference_lengths: one per link pair");
  }

  double operator()(const Eigen::Matrix2Xd& X0, Eigen::Matrix2Xd* gradient) {
    const Eigen::Index n = X0.cols();
    if (gradient) gradient->setZero(2, n);
    if (!X0.allFinite()) return kInfinity;
    const std::vector<double> signs = orientations(order_, X0);
    for (std::size_t t = 0; t < signs.size(); ++t)
      if (!(signs[t] * signs_[t] > 0)) return kInfinity;
    if (!kinematics_.set_initial_positions(X0)) return kInfinity;
    kinematics_.reset_continuation();

    double energy = 0;
    // Initial-configuration terms: drags without an angle, regularization.
    for (const auto& drag : objectives_.drags) {
      if (drag.angle) continue;
      const Eigen::Vector2d r = X0.col(drag.joint) - drag.target;
      energy += 0.5 * drag.weight * r.squaredNorm();
      if (gradient) gradient->col(drag.joint) += drag.weight * r;
    }
    for (std::size_t p = 0; p < pairs_.size(); ++p) {
      const auto [i, j] = pairs_[p];
      const Eigen::Vector2d d = X0.col(j) - X0.col(i);
      const double length = d.norm(), r = length - references_[p];
      energy += 0.5 * objectives_.regularization_weight * r * r;
      if (gradient) {
        const Eigen::Vector2d g = objectives_.regularization_weight * r * d / length;
        gradient->col(j) += g;
        gradient->col(i) -= g;
      }
    }

    // Terms over the motion: one reconstruction (with derivatives) per sample angle.
    const double per_sample = 1.0 / static_cast<double>(angles_.size());
    G_.resize(2, n);
    for (std::size_t s = 0; s < angles_.size(); ++s) {
      if (!(gradient ? kinematics_.solve(angles_[s], X_, tape_) : kinematics_.solve(angles_[s], X_))) return kInfinity;
      G_.setZero();
      for (const auto& trajectory : objectives_.trajectories) {
        const Eigen::Vector2d r = X_.col(trajectory.joint) - trajectory.curve[s];
        energy += 0.5 * trajectory.weight * per_sample * r.squaredNorm();
        G_.col(trajectory.joint) += trajectory.weight * per_sample * r;
      }
      if (objectives_.envelope) {
        const auto& box = *objectives_.envelope;
        for (Eigen::Index k = 0; k < n; ++k) {
          const Eigen::Vector2d below = (box.min - X_.col(k)).cwiseMax(0.0);
          const Eigen::Vector2d above = (X_.col(k) - box.max).cwiseMax(0.0);
          const Eigen::Vector2d r = above - below;
          if (r.isZero()) continue;
          energy += 0.5 * box.weight * per_sample * r.squaredNorm();
          G_.col(k) += box.weight * per_sample * r;
        }
      }
      barrier(per_sample, energy);
      if (gradient) tape_.pull_back(G_, *gradient);
    }
    // Drags in a current configuration: their own reconstruction.
    for (const auto& drag : objectives_.drags) {
      if (!drag.angle) continue;
      if (!(gradient ? kinematics_.solve(*drag.angle, X_, tape_) : kinematics_.solve(*drag.angle, X_)))
        return kInfinity;
      const Eigen::Vector2d r = X_.col(drag.joint) - drag.target;
      energy += 0.5 * drag.weight * r.squaredNorm();
      G_.setZero();
      G_.col(drag.joint) = drag.weight * r;
      if (gradient) tape_.pull_back(G_, *gradient);
    }
    return energy;
  }

  const std::vector<double>& angles() const { return angles_; }

 private:
  // Eq. (6–7) on every triangle rule at the current sample: adds to the energy and to G_.
  void barrier(double per_sample, double& energy) {
    const double epsilon = objectives_.singularity_epsilon, weight = objectives_.singularity_weight * per_sample;
    const Eigen::Matrix2d P = detail::perp_matrix();
    for (const Rule& rule : order_.rules) {
      if (rule.kind != RuleKind::kTriangle) continue;
      const Eigen::Vector2d u = X_.col(rule.i) - X_.col(rule.k), v = X_.col(rule.j) - X_.col(rule.k);
      const double uu = u.squaredNorm(), vv = v.squaredNorm(), c = detail::cross(u, v);
      const double ds = c * c / (uu * vv);
      if (ds >= epsilon) continue;
      const double log_ratio = std::log(ds / epsilon);
      energy += 0.5 * weight * log_ratio * log_ratio;
      const double df = weight * log_ratio / ds;  // d(½ log²(ds/ε))/d ds
      const Eigen::Vector2d dc_du(v.y(), -v.x());
      const Eigen::Vector2d dds_du = 2 * c * dc_du / (uu * vv) - 2 * ds * u / uu;
      const Eigen::Vector2d dds_dv = 2 * c * (P * u) / (uu * vv) - 2 * ds * v / vv;
      G_.col(rule.i) += df * dds_du;
      G_.col(rule.j) += df * dds_dv;
      G_.col(rule.k) -= df * (dds_du + dds_dv);
    }
  }

  EditObjectives objectives_;
  JointOrder order_;
  SymbolicKinematics kinematics_;
  std::vector<double> angles_;
  std::vector<std::pair<int, int>> pairs_;
  std::vector<double> references_;
  std::vector<double> signs_;
  Eigen::Matrix2Xd X_, G_;
  StateTape tape_;  // reverse-mode gradients: O(#rules) per sample
};

// The motion still works as before: same rocking/turning behaviour, no dead point crossed.
bool still_works(const Linkage& original, const MotionRange& before, const Eigen::Matrix2Xd& X0) {
  Linkage candidate = original;
  candidate.set_initial_positions(X0);
  try {
    const SymbolicKinematics kinematics(candidate, order_joints(original));
    const MotionRange after = motion_range(kinematics);
    if (before.full_rotation) return after.full_rotation;
    const std::vector<double> angles = edit_sample_angles(original, 72);
    return !after.full_rotation ? after.contains(angles.front()) && after.contains(angles.back()) : true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

std::vector<std::pair<int, int>> link_pairs(const Linkage& linkage) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& link : linkage.links)
    for (std::size_t a = 0; a < link.size(); ++a)
      for (std::size_t b = a + 1; b < link.size(); ++b) pairs.emplace_back(link[a], link[b]);
  return pairs;
}

std::vector<double> link_lengths(const Linkage& linkage) {
  std::vector<double> lengths;
  for (const auto& [i, j] : link_pairs(linkage))
    lengths.push_back((linkage.joints[i].position - linkage.joints[j].position).norm());
  return lengths;
}

std::vector<double> edit_sample_angles(const Linkage& linkage, int samples) {
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  const MotionRange range = motion_range(kinematics);
  std::vector<double> angles;
  if (range.full_rotation) {
    for (int s = 0; s < samples; ++s) angles.push_back(range.lower + 2 * std::numbers::pi * s / samples);
  } else {
    const double margin = 0.02 * (range.upper - range.lower);
    for (int s = 0; s < samples; ++s)
      angles.push_back(range.lower + margin + (range.upper - range.lower - 2 * margin) * s / std::max(1, samples - 1));
  }
  return angles;
}

std::vector<Eigen::Vector2d> joint_trajectory(const Linkage& linkage, int joint, const std::vector<double>& angles) {
  const SymbolicKinematics kinematics(linkage, order_joints(linkage));
  std::vector<Eigen::Vector2d> curve;
  Eigen::Matrix2Xd X;
  ReconstructionFailure failure;
  for (double angle : angles) {
    if (!kinematics.solve(angle, X, &failure)) throw InputError("", "", failure.message);
    curve.push_back(X.col(joint));
  }
  return curve;
}

class EditEnergy::Impl : public EditProblem {
 public:
  using EditProblem::EditProblem;
};

EditEnergy::EditEnergy(const Linkage& original, const EditObjectives& objectives, const EditSettings& settings)
    : impl_(std::make_unique<Impl>(original, objectives, settings)) {}
EditEnergy::~EditEnergy() = default;

double EditEnergy::operator()(const Eigen::Matrix2Xd& X0, Eigen::Matrix2Xd* gradient) { return (*impl_)(X0, gradient); }

const std::vector<double>& EditEnergy::sample_angles() const { return impl_->angles(); }

double edit_energy(const Linkage& original, const EditObjectives& objectives, const EditSettings& settings,
                   const Eigen::Matrix2Xd& X0, Eigen::Matrix2Xd* gradient) {
  return EditEnergy(original, objectives, settings)(X0, gradient);
}

EditResult edit_linkage(const Linkage& linkage, const EditObjectives& objectives, const EditSettings& settings) {
  EditProblem problem(linkage, objectives, settings);
  const Eigen::Matrix2Xd start = linkage.initial_positions();
  const Eigen::Index n = start.cols();
  EditResult result;
  result.linkage = linkage;
  result.energy_before = problem(start, nullptr);

  // Every initial position is a parameter, fixed joints included (the paper edits the
  // whole initial configuration); hold joints in place with drags to their positions.
  Eigen::Matrix2Xd best = start;
  double best_energy = result.energy_before;
  auto objective = [&](const Eigen::VectorXd& x, Eigen::VectorXd& grad) {
    const Eigen::Map<const Eigen::Matrix2Xd> X0(x.data(), 2, n);
    Eigen::Matrix2Xd G;
    const double energy = problem(X0, &G);
    grad = Eigen::Map<const Eigen::VectorXd>(G.data(), 2 * n);
    if (energy < best_energy) best_energy = energy, best = X0;
    return energy;
  };
  LBFGSpp::LBFGSParam<double> param;
  param.epsilon = settings.gradient_tolerance;
  param.epsilon_rel = settings.gradient_tolerance;
  param.max_iterations = settings.max_iterations;
  param.past = 3;
  param.delta = 1e-10;
  param.max_linesearch = 60;
  LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchBacktracking> solver(param);
  Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(start.data(), 2 * n);
  double fx = 0;
  try {
    result.iterations = solver.minimize(objective, x, fx);
    result.status = result.iterations >= settings.max_iterations ? "iteration limit reached" : "converged";
  } catch (const std::exception& error) {
    result.status = std::string("stopped: ") + error.what();
  }

  // Final safeguard: the best configuration must keep the motion working; shorten the
  // displacement until it does.
  const MotionRange before = motion_range(SymbolicKinematics(linkage, order_joints(linkage)));
  Eigen::Matrix2Xd delta = best - start;
  while (!delta.isZero() && !still_works(linkage, before, start + delta)) {
    delta *= 0.5;
    ++result.shortened;
    if (result.shortened > 40) delta.setZero();
  }
  result.linkage.set_initial_positions(start + delta);
  result.energy_after = problem(start + delta, nullptr);
  return result;
}

}  // namespace reconfig::linkage
