#pragma once
/// @file
/// Joint ordering (LinkEdit, Algorithm 1): the sequence in which joint positions can be
/// reconstructed from the motor value, each by a closed-form rule, plus Newton blocks for
/// complex kinematic loops the rules cannot solve.

#include <string>
#include <vector>

#include "reconfig/linkage/linkage.h"

namespace reconfig::linkage {

/// How one joint (or, for kNewtonBlock, a group of joints) is reconstructed.
enum class RuleKind {
  kFixed,        ///< x_k = x̄_k
  kMotor,        ///< x_k = x_c + |x̄_k − x̄_c| (cos m, sin m), c = motor center
  kTriangle,     ///< (i, j) → k by the law of cosines (eq. 1–2), orientation of x̄ kept
  kRigid,        ///< i, j, k on one link: x_k = x_i + a (x_j − x_i) + b ⟂(x_j − x_i)
  kNewtonBlock,  ///< `block` joints solved together by Newton's method (complex loop)
};

/// One step of the reconstruction.
struct Rule {
  RuleKind kind = RuleKind::kFixed;
  int k = -1;      ///< the reconstructed joint (unused for kNewtonBlock)
  int i = -1;      ///< first known joint (kMotor: the motor center)
  int j = -1;      ///< second known joint
  int block = -1;  ///< index into JointOrder::blocks for kNewtonBlock
};

/// A group of joints of a complex kinematic loop, solved simultaneously. Each link touching
/// the block contributes its rigidity as equations over the joints it carries that are in
/// the block or already known: |x_r1 − x_r0|² = l², and x_m = x_r0 + a (x_r1 − x_r0) +
/// b ⟂(x_r1 − x_r0) for its other joints. Equations = 2 × #joints.
struct NewtonBlock {
  std::vector<int> joints;  ///< the unknown joints of the block
  struct LinkEquations {
    int r0 = -1, r1 = -1;     ///< reference joints
    std::vector<int> others;  ///< further joints of the link involved
  };
  std::vector<LinkEquations> links;
};

/// The result of ordering: rules in reconstruction order (each joint reconstructed exactly
/// once, inputs always earlier), and the joints the closed-form rules could not solve.
struct JointOrder {
  std::vector<Rule> rules;
  std::vector<NewtonBlock> blocks;
  std::vector<int> stuck_joints;  ///< joints of complex loops (in Newton blocks), sorted
  bool symbolic() const { return blocks.empty(); }
};

/// Orders the joints (Algorithm 1). Starts from the fixed joints and the motor joint; a
/// joint with two known neighbours gets a rule: kRigid when a link carries it and two known
/// joints, else kTriangle, choosing among known neighbour pairs the best-conditioned
/// triangle in the initial configuration (largest |sin| of the angle at k). When the rules
/// get stuck, the smallest group of unknown joints whose link equations determine them is
/// made a Newton block, and ordering goes on.
/// @throws reconfig::InputError (without a file) if some joints cannot be determined at all
///         (under-constrained: the message names them), e.g. `joints[4]: joints "E", "F"
///         are not determined by the links (the linkage is under-constrained)`
JointOrder order_joints(const Linkage& linkage);

/// "(B, C) → D"-style description of a rule, with joint names.
std::string describe_rule(const Linkage& linkage, const JointOrder& order, const Rule& rule);

}  // namespace reconfig::linkage
