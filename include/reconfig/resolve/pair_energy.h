#pragma once
/// @file
/// The intersection energy of two parts over a stretch of a transition (reconfigurables §6.3,
/// eq. 1), its severity time, and its gradient with respect to the parts' rigid motion at each
/// sample time (§6.4, eq. 2).

#include <vector>

#include "reconfig/resolve/shape_cache.h"
#include "reconfig/resolve/twist_gradient.h"
#include "reconfig/scene/reconfigurable.h"

namespace reconfig::resolve {

/// The energy density at one time: e(t) = ‖Ic(t)‖ + P(t) + D(t), the contour length, the
/// penetration term (`penetration.h`) and the proximity deficit (`proximity.h`), all lengths.
/// D = c wherever the parts overlap (a contour or a sample inside), so e is continuous as
/// they come into contact.
struct EnergySample {
  double time = 0;
  double weight = 0;          ///< quadrature weight of the sample in the energy integral
  double contour_length = 0;  ///< ‖Ic(t)‖
  double penetration = 0;     ///< P(t)
  double proximity = 0;       ///< D(t); 0 without a reach
  /// ∂e(t)/∂(rigid motion of part a at t), part b still (for part b: the negative).
  TwistGradient gradient;
  double density() const { return contour_length + penetration + proximity; }
};

struct PairEnergy {
  /// E = ∫ e(t) dt over the request's [t0, t1]: the paper's contour energy plus the
  /// penetration energy, so that a part wholly inside another, or boxes overlapping face-on,
  /// also have an energy that falls as they come apart, plus the proximity energy, so that a
  /// near miss the detector reports (parts within its tolerance) has one too.
  double energy = 0;
  double contour_energy = 0;      ///< ∫ ‖Ic(t)‖ dt (eq. 1)
  double penetration_energy = 0;  ///< ∫ P(t) dt
  double proximity_energy = 0;    ///< ∫ D(t) dt
  /// argmax ‖Ic(t)‖ over the samples; argmax P(t) when no sample has a contour (containment);
  /// argmax D(t) (the closest approach) when neither; the middle of [t0, t1] when the energy
  /// is 0.
  double severity_time = 0;
  std::vector<EnergySample> samples;  ///< by time; their weights integrate e
};

struct PairEnergyRequest {
  int transition = 0;
  int part_a = 0, part_b = 1;
  double t0 = 0, t1 = 1;
  /// The trapezoid rule on uniform samples is refined (the number of intervals doubled) until
  /// a doubling changes E by less than this fraction of it right after one that changed it by
  /// less than four times that fraction.
  double relative_accuracy = 0.01;
  /// The proximity term's reach c (scene units; `proximity_reach`): 0 leaves the term out.
  double proximity_reach = 0;
  int min_intervals = 16;
  int max_intervals = 1024;
};

/// The energy of parts a and b over [t0, t1] of a transition. Samples are evaluated in
/// parallel; the result does not depend on the number of threads.
PairEnergy pair_energy(const scene::Reconfigurable& scene, ShapeCache& shapes, const PairEnergyRequest& request);

}  // namespace reconfig::resolve
