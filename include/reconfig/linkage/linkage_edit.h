#pragma once
/// @file
/// Function-preserving linkage editing (LinkEdit §4): objectives on joint positions,
/// trajectories and the motion envelope, length regularization, the singularity barrier
/// (eq. 6–7), minimized with L-BFGS over the initial configuration x̄ (eq. 8).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reconfig/linkage/linkage.h"

namespace reconfig::linkage {

/// What the user asks for. Weights are per term; distances are in the linkage's units.
struct EditObjectives {
  /// Eq. (3): pull a joint to `target`, in the initial configuration (`angle` unset) or in
  /// the configuration at motor value `*angle` (radians).
  struct JointDrag {
    int joint = -1;
    Eigen::Vector2d target = Eigen::Vector2d::Zero();
    std::optional<double> angle;
    double weight = 1;
  };
  std::vector<JointDrag> drags;

  /// Eq. (4): the joint's positions at the edit's sample angles should follow `curve`
  /// (one point per sample angle, see edit_sample_angles).
  struct Trajectory {
    int joint = -1;
    std::vector<Eigen::Vector2d> curve;
    double weight = 1;
  };
  std::vector<Trajectory> trajectories;

  /// Motion envelope: every joint at every sample angle should stay inside [min, max].
  struct Envelope {
    Eigen::Vector2d min, max;
    double weight = 1;
  };
  std::optional<Envelope> envelope;

  /// Eq. (5): ½ Σ (l_ij − l̃_ij)² over the joint pairs of every link, towards
  /// `reference_lengths` (one per pair, in link_pairs order; empty: the lengths of the
  /// linkage being edited). Update the references after each edit (link_lengths).
  double regularization_weight = 0.1;
  std::vector<double> reference_lengths;

  /// Eq. (6–7): for d_s < ε, ½ log²(d_s / ε) per reconstruction triangle and sample.
  double singularity_weight = 1;
  double singularity_epsilon = 0.05;
};

struct EditSettings {
  int samples = 72;            ///< motor angles the motion is sampled at
  int max_iterations = 200;    ///< L-BFGS iterations
  double gradient_tolerance = 1e-8;
};

struct EditResult {
  Linkage linkage;              ///< the edited linkage (the input if nothing could be done)
  double energy_before = 0, energy_after = 0;
  int iterations = 0;
  int shortened = 0;            ///< times the final step was halved to keep the motion intact
  std::string status;           ///< how the optimizer stopped
};

/// The (i, j) joint pairs regularization measures: every pair of joints on every link.
std::vector<std::pair<int, int>> link_pairs(const Linkage& linkage);
/// Their lengths in the initial configuration.
std::vector<double> link_lengths(const Linkage& linkage);

/// The motor angles (radians) an edit samples: `samples` angles over a full turn from the
/// initial angle, or spread over the rocking range (2% inside each dead point).
std::vector<double> edit_sample_angles(const Linkage& linkage, int samples);

/// The positions of `joint` at `angles`. @throws reconfig::InputError if some angle cannot
/// be reconstructed
std::vector<Eigen::Vector2d> joint_trajectory(const Linkage& linkage, int joint, const std::vector<double>& angles);

/// The edit energy (eq. 8) as a function of the initial configuration x̄, set up once for
/// repeated evaluation (an interactive editor evaluates it at every optimizer step).
class EditEnergy {
 public:
  /// @param original the linkage being edited: its rule order, triangle orientations and
  ///        motion range (which fixes the sample angles) are kept
  EditEnergy(const Linkage& original, const EditObjectives& objectives, const EditSettings& settings = {});
  ~EditEnergy();
  EditEnergy(const EditEnergy&) = delete;
  EditEnergy& operator=(const EditEnergy&) = delete;

  /// The energy at x̄ = X0 (2×#J) and, if `gradient` is not null, ∂E/∂x̄ (2×#J, by
  /// reverse-mode differentiation through the rules). +∞ if X0 breaks the linkage: a
  /// triangle cannot close at some sample, or a reconstruction triangle flips orientation
  /// or degenerates in X0.
  double operator()(const Eigen::Matrix2Xd& X0, Eigen::Matrix2Xd* gradient);

  /// The motor angles (radians) the motion terms are sampled at.
  const std::vector<double>& sample_angles() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-shot EditEnergy evaluation (sets up, evaluates once).
double edit_energy(const Linkage& original, const EditObjectives& objectives, const EditSettings& settings,
                   const Eigen::Matrix2Xd& X0, Eigen::Matrix2Xd* gradient);

/// Minimizes the energy with L-BFGS from the linkage's initial configuration. A step that
/// would break the linkage gets infinite energy and is shortened by the line search; the
/// result is checked with a fine motion-range scan (a crank that turned fully still does)
/// and the displacement halved until it passes.
EditResult edit_linkage(const Linkage& linkage, const EditObjectives& objectives, const EditSettings& settings = {});

/// A sequence of edits, as in an interactive editor: each edit regularizes towards the link
/// lengths left by the previous one ("we update the reference distances after each editing
/// operation", §4.1), and the linkage after each edit is the start of the next.
class EditSession {
 public:
  explicit EditSession(Linkage linkage, EditSettings settings = {})
      : linkage_(std::move(linkage)), settings_(settings), references_(link_lengths(linkage_)) {}

  const Linkage& linkage() const { return linkage_; }
  const std::vector<double>& reference_lengths() const { return references_; }

  /// Runs one edit (objectives.reference_lengths is replaced by the session's), keeps its
  /// result and updates the references.
  EditResult edit(EditObjectives objectives) {
    objectives.reference_lengths = references_;
    EditResult result = edit_linkage(linkage_, objectives, settings_);
    linkage_ = result.linkage;
    references_ = link_lengths(linkage_);
    return result;
  }

 private:
  Linkage linkage_;
  EditSettings settings_;
  std::vector<double> references_;
};

}  // namespace reconfig::linkage
