#include "sculpt/detail/half_step.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

namespace reconfig::sculpt::detail {
namespace {

constexpr int kMaxNewtonIterations = 60;
constexpr int kMaxFixedPointIterations = 300;

bool close_enough(const Eigen::Vector3d& step, const Eigen::Vector3d& p) {
  return step.norm() <= kSolveTolerance * (1 + p.norm());
}

}  // namespace

Eigen::Vector3d reflect(const MirrorPlane& mirror, const Eigen::Vector3d& p) {
  Eigen::Vector3d q = p;
  q[mirror.axis] = 2 * mirror.offset - p[mirror.axis];
  return q;
}

bool ClosedFormHalfStep::apply(const Eigen::Vector3d& p, Eigen::Vector3d& image, Eigen::Matrix3d& J) const {
  Eigen::Vector3d gradient;
  const double w = tool_.field(p, gradient);
  if (w == 0) {
    image = p;
    J.setIdentity();
    return false;
  }
  const double alpha = c_ * w;
  image = motion_.apply(p, alpha);
  J = motion_.linear(alpha) + c_ * motion_.velocity(p, alpha) * gradient.transpose();
  return true;
}

// G(p) = p − (−c φ(p)) ⊙ M y = 0, ∂G/∂p = I + u ∇φᵀ with u = c (log M)((−cφ) ⊙ M y). The
// Jacobian of E at the solution comes from the last iterate's field (it moved by < tolerance).
bool ClosedFormHalfStep::solve(const Eigen::Vector3d& y, Eigen::Vector3d& p, Eigen::Matrix3d& J) const {
  p = y;
  Eigen::Vector3d gradient;
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    const double w = tool_.field(p, gradient);
    if (iteration == 0 && w == 0) {  // out of reach: E(y) = y
      J.setIdentity();
      return true;
    }
    const double alpha = -c_ * w;
    const Eigen::Vector3d residual = p - motion_.apply(y, alpha);
    const Eigen::Vector3d u = c_ * motion_.velocity(y, alpha);
    const double denominator = 1 + gradient.dot(u);
    if (!(denominator > 0)) return false;
    const Eigen::Vector3d step = residual - u * (gradient.dot(residual) / denominator);
    p -= step;
    if (close_enough(step, p)) {
      J = motion_.linear(c_ * w) + c_ * motion_.velocity(p, c_ * w) * gradient.transpose();
      return true;
    }
  }
  return false;
}

BlendedHalfStep::BlendedHalfStep(const std::vector<Tool>& tools, const std::vector<ToolMotion>& motions,
                                 const MirrorPlane& mirror, double c)
    : tools_(tools), mirror_(mirror), c_(c) {
  Eigen::Matrix4d reflection = Eigen::Matrix4d::Identity();
  if (mirror.axis >= 0) {
    reflection(mirror.axis, mirror.axis) = -1;
    reflection(mirror.axis, 3) = 2 * mirror.offset;
  }
  double smallest_coating = tools.front().coating();
  for (int j = 0; j < static_cast<int>(tools.size()); ++j) {
    terms_.push_back({j, false, motions[j].log_matrix()});
    if (mirror.axis >= 0) terms_.push_back({j, true, reflection * motions[j].log_matrix() * reflection});
    smallest_coating = std::min(smallest_coating, tools[j].coating());
  }
  step_ = 1e-6 * smallest_coating;
}

bool BlendedHalfStep::blended_log(const Eigen::Vector3d& p, Eigen::Matrix4d& log) const {
  double sum = 0, untouched = 1;
  std::vector<double> phi(terms_.size());
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    const Tool& tool = tools_[terms_[i].tool];
    phi[i] = tool.field(terms_[i].mirrored ? reflect(mirror_, p) : p);
    sum += phi[i];
    untouched *= 1 - phi[i];
  }
  if (sum == 0) return false;
  log.setZero();
  for (std::size_t i = 0; i < terms_.size(); ++i) log += phi[i] * (1 - untouched) / sum * terms_[i].log;
  return true;
}

Eigen::Vector3d BlendedHalfStep::map(const Eigen::Vector3d& p, const Eigen::Vector3d& at, double scale) const {
  Eigen::Matrix4d log;
  if (!blended_log(at, log)) return p;
  const Eigen::Matrix4d transform = (scale * log).exp();
  return transform.topLeftCorner<3, 3>() * p + transform.topRightCorner<3, 1>();
}

bool BlendedHalfStep::apply(const Eigen::Vector3d& p, Eigen::Vector3d& image, Eigen::Matrix3d& J) const {
  Eigen::Matrix4d log;
  if (!blended_log(p, log)) {
    image = p;
    J.setIdentity();
    return false;
  }
  image = map(p, p, c_);
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d e = step_ * Eigen::Vector3d::Unit(axis);
    J.col(axis) = (map(p + e, p + e, c_) - map(p - e, p - e, c_)) / (2 * step_);
  }
  return true;
}

bool BlendedHalfStep::solve(const Eigen::Vector3d& y, Eigen::Vector3d& p, Eigen::Matrix3d& J) const {
  p = y;
  Eigen::Matrix4d log;
  if (!blended_log(y, log)) {
    J.setIdentity();
    return true;
  }
  for (int iteration = 0; iteration < kMaxFixedPointIterations; ++iteration) {
    const Eigen::Vector3d next = map(y, p, -c_);
    const Eigen::Vector3d step = next - p;
    p = next;
    if (close_enough(step, p)) {
      Eigen::Vector3d image;
      apply(p, image, J);
      return true;
    }
  }
  return false;
}

}  // namespace reconfig::sculpt::detail
