#pragma once
/// @file
/// A half-step of a stroke's sub-step: the map E(p) = (c·w(p)) ⊙ M p of the tools placed where
/// they are at one instant, its Jacobian and its inverse.

#include <Eigen/Core>

#include <vector>

#include "reconfig/sculpt/sculpt_stroke.h"
#include "reconfig/sculpt/tool.h"
#include "reconfig/sculpt/tool_motion.h"

namespace reconfig::sculpt::detail {

/// Points are solved to this absolute tolerance times (1 + ‖p‖).
inline constexpr double kSolveTolerance = 1e-13;

class HalfStep {
 public:
  virtual ~HalfStep() = default;
  /// E(p) in `image` and ∂E/∂p in `J`; false (image = p, J = I exactly) where no tool reaches p.
  virtual bool apply(const Eigen::Vector3d& p, Eigen::Vector3d& image, Eigen::Matrix3d& J) const = 0;
  /// The point p with E(p) = y, in `p`, and ∂E/∂p there in `J`; false if it could not be found
  /// (E not invertible there). Where no tool reaches y, p = y and J = I exactly.
  virtual bool solve(const Eigen::Vector3d& y, Eigen::Vector3d& p, Eigen::Matrix3d& J) const = 0;
};

/// One tool, closed forms (§4.1–4.3): E(p) = (c φ(p)) ⊙ M p, J = A(α) + c (log M E(p)) ∇φᵀ,
/// inverted by Newton's method (the rank-one Jacobian inverted by Sherman–Morrison).
class ClosedFormHalfStep final : public HalfStep {
 public:
  /// @param tool  placed where it is at this instant (kept by reference)
  ClosedFormHalfStep(const Tool& tool, const ToolMotion& motion, double c) : tool_(tool), motion_(motion), c_(c) {}
  bool apply(const Eigen::Vector3d& p, Eigen::Vector3d& image, Eigen::Matrix3d& J) const override;
  bool solve(const Eigen::Vector3d& y, Eigen::Vector3d& p, Eigen::Matrix3d& J) const override;

 private:
  const Tool& tool_;
  const ToolMotion& motion_;
  double c_;
};

/// Several tools (and their mirror images), blended in matrix-log space (eq. 2):
/// E(p) = exp(c Σ_j β_j(p) log M_j) p with β_j = φ_j (1 − Π_k(1 − φ_k)) / Σ_k φ_k; Jacobian by
/// central differences, inverse by fixed-point iteration p ← exp(−c L(p)) y.
class BlendedHalfStep final : public HalfStep {
 public:
  /// @param tools   placed where they are at this instant (copied)
  /// @param mirror  each tool also acts mirrored in this plane (axis −1: no mirror)
  BlendedHalfStep(const std::vector<Tool>& tools, const std::vector<ToolMotion>& motions, const MirrorPlane& mirror,
                  double c);
  bool apply(const Eigen::Vector3d& p, Eigen::Vector3d& image, Eigen::Matrix3d& J) const override;
  bool solve(const Eigen::Vector3d& y, Eigen::Vector3d& p, Eigen::Matrix3d& J) const override;

 private:
  struct Term {
    int tool = 0;
    bool mirrored = false;
    Eigen::Matrix4d log = Eigen::Matrix4d::Zero();  ///< log M_j (reflected for a mirror image)
  };
  /// Σ_j β_j(p) log M_j; false where every φ_j(p) = 0.
  bool blended_log(const Eigen::Vector3d& p, Eigen::Matrix4d& log) const;
  /// exp(scale · log) p, or p where no tool reaches it.
  Eigen::Vector3d map(const Eigen::Vector3d& p, const Eigen::Vector3d& at, double scale) const;

  std::vector<Tool> tools_;
  MirrorPlane mirror_;
  std::vector<Term> terms_;
  double c_;
  double step_;  ///< finite-difference step
};

/// The reflection of p in the mirror plane.
Eigen::Vector3d reflect(const MirrorPlane& mirror, const Eigen::Vector3d& p);

}  // namespace reconfig::sculpt::detail
