#include "reconfig/linkage/linkage_motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "reconfig/common/input_error.h"
#include "reconfig/motion/screw_motion.h"

namespace reconfig::linkage {
namespace {

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

Eigen::Isometry3d link_frame(const Eigen::Matrix2Xd& X, int origin, int toward, const PlanePlacement& plane) {
  const Eigen::Vector2d o = X.col(origin);
  const Eigen::Vector2d d = X.col(toward) - o;
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  frame.linear() = Eigen::AngleAxisd(std::atan2(d.y(), d.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  frame.translation() = Eigen::Vector3d(plane.scale * o.x(), plane.scale * o.y(), 0.0);
  return plane.pose * frame;
}

Eigen::Isometry3d attached_map(const Eigen::Matrix2Xd& X, const LinkAttachment& attachment,
                               const PlanePlacement& plane) {
  return link_frame(X, attachment.origin, attachment.toward, plane) * attachment.offset;
}

bool share_a_link(const Linkage& linkage, int origin, int toward) {
  if (origin == toward) return false;
  for (const auto& link : linkage.links)
    if (std::find(link.begin(), link.end(), origin) != link.end() &&
        std::find(link.begin(), link.end(), toward) != link.end())
      return true;
  return false;
}

std::string motor_interval_error(const MotionRange& range, double from, double to) {
  if (range.full_rotation) return "";
  const double turn = 2 * std::numbers::pi, slack = 1e-12;
  const double lo = std::min(from, to), hi = std::max(from, to);
  const double shift = std::ceil((range.lower - lo) / turn - slack) * turn;  // lo + shift ≥ lower
  if (lo + shift <= range.upper + slack && hi + shift <= range.upper + slack) return "";
  return fmt::format("the motor cannot turn from {:.1f}° to {:.1f}°: the linkage {}", degrees(from), degrees(to),
                     range.describe());
}

double placement_distance(const Eigen::Isometry3d& A, const Eigen::Isometry3d& B, const Eigen::Vector3d& center,
                          double radius) {
  // ‖R_A − R_B‖₂ = ‖R_A R_Bᵀ − I‖₂ = 2 sin(φ/2) = 2 |vec(q)| for the unit quaternion q of R_A R_Bᵀ.
  const Eigen::Quaterniond q(Eigen::Matrix3d(A.linear() * B.linear().transpose()));
  return (A * center - B * center).norm() + radius * 2.0 * std::min(1.0, q.normalized().vec().norm());
}

LinkageMotion::LinkageMotion(const SymbolicKinematics& kinematics, PlanePlacement plane, double from, double to)
    : kinematics_(kinematics), plane_(std::move(plane)), from_(from), to_(to) {}

bool LinkageMotion::joints_at(double t, Eigen::Matrix2Xd& X, ReconstructionFailure* failure) const {
  return kinematics_.solve(angle_at(t), X, failure);
}

std::vector<Eigen::Isometry3d> LinkageMotion::maps_at(double t, const std::vector<AttachedBody>& bodies) const {
  Eigen::Matrix2Xd X;
  ReconstructionFailure failure;
  if (!joints_at(t, X, &failure))
    throw InputError("", "motor", fmt::format("the linkage cannot be reconstructed at motor angle {:.3f}°: {}",
                                              degrees(angle_at(t)), failure.message));
  std::vector<Eigen::Isometry3d> maps;
  maps.reserve(bodies.size());
  for (const AttachedBody& body : bodies) {
    maps.push_back(attached_map(X, body.attachment, plane_));
    if (!maps.back().matrix().allFinite())
      throw InputError("", "", "the placement in 3D is not finite (plane, scale or offsets too large)");
  }
  return maps;
}

namespace {

struct Compiler {
  [[noreturn]] void too_many_keys() const {
    throw InputError("", "tolerance",
                     fmt::format("following the linkage within {} would take more than {} key poses (a tolerance far "
                                 "too small for the size of the parts, or too many turns)",
                                 request.tolerance, request.max_keys));
  }

  const LinkageMotion& motion;
  const CompileMotionRequest& request;
  CompiledMotion result;
  std::vector<std::vector<Eigen::Isometry3d>> maps;  // per key time, per body

  void push(double t, std::vector<Eigen::Isometry3d> at) {
    if (static_cast<long long>(result.times.size()) >= request.max_keys) too_many_keys();
    result.times.push_back(t);
    maps.push_back(std::move(at));
  }

  // Refines (a, b]: `left` are the maps at a (the last pushed), `right` those at b.
  void refine(double a, double b, const std::vector<Eigen::Isometry3d>& left, std::vector<Eigen::Isometry3d> right) {
    const std::size_t n = request.bodies.size();
    std::vector<motion::ScrewMotion> screws;
    screws.reserve(n);
    for (std::size_t i = 0; i < n; ++i) screws.emplace_back(left[i], right[i]);
    double worst = 0;
    const int checks = std::max(1, request.checks_per_segment);
    for (int s = 1; s <= checks; ++s) {
      const double f = static_cast<double>(s) / (checks + 1);
      const std::vector<Eigen::Isometry3d> truth = motion.maps_at(a + f * (b - a), request.bodies);
      for (std::size_t i = 0; i < n; ++i) {
        const double d = placement_distance(screws[i].at(f), truth[i], request.bodies[i].center,
                                            request.bodies[i].radius);
        worst = std::isnan(d) ? std::numeric_limits<double>::infinity() : std::max(worst, d);
      }
    }
    if (worst > 0.5 * request.tolerance) {
      if (!(b - a > request.min_segment))
        throw InputError("", "tolerance",
                         fmt::format("the motion cannot be followed within {}: {} remain between key poses {} apart "
                                     "in time (a tolerance far too small for the size of the parts?)",
                                     request.tolerance, worst, b - a));
      const double m = 0.5 * (a + b);
      std::vector<Eigen::Isometry3d> middle = motion.maps_at(m, request.bodies);
      refine(a, m, left, middle);
      refine(m, b, middle, std::move(right));
      return;
    }
    result.deviation = std::max(result.deviation, worst);
    push(b, std::move(right));
  }
};

}  // namespace

CompiledMotion compile_motion(const LinkageMotion& motion, const CompileMotionRequest& request) {
  assert(request.tolerance > 0 && request.initial_step > 0);
  Compiler compiler{motion, request, {}, {}};
  const double turn = std::abs(motion.angle_at(1) - motion.angle_at(0));
  const double initial = std::ceil(turn / request.initial_step - 1e-9);
  if (!(initial < request.max_keys)) compiler.too_many_keys();
  const int segments = std::max(1, static_cast<int>(initial));
  compiler.push(0.0, motion.maps_at(0.0, request.bodies));
  for (int s = 1; s <= segments; ++s) {
    const double a = static_cast<double>(s - 1) / segments, b = s == segments ? 1.0 : static_cast<double>(s) / segments;
    const std::vector<Eigen::Isometry3d> left = compiler.maps.back();
    compiler.refine(a, b, left, motion.maps_at(b, request.bodies));
  }
  CompiledMotion& result = compiler.result;
  result.keys.assign(request.bodies.size(), {});
  for (std::size_t i = 0; i < request.bodies.size(); ++i) {
    result.keys[i].reserve(result.times.size());
    for (std::size_t k = 0; k < result.times.size(); ++k) {
      motion::Pose pose = motion::Pose::from_isometry(compiler.maps[k][i], request.bodies[i].center);
      pose.rotation.normalize();
      result.keys[i].push_back({result.times[k], pose});
    }
  }
  return std::move(compiler.result);
}

}  // namespace reconfig::linkage
