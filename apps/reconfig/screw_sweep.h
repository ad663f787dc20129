#pragma once
/// @file
/// `reconfig sweep --method screw`: the screw-motion envelope of a part (docs/file-formats.md).

#include "reconfig/geometry/mesh.h"
#include "reconfig/sweep/relative_motion.h"
#include "reconfig/sweep/screw_envelope.h"

namespace reconfig::cli {

struct ScrewSweep {
  sweep::ScrewEnvelope envelope;
  int screws = 0;            ///< screws the motion was cut into
  double motion_error = 0;   ///< the largest displacement bound over one screw's time span
};

/// The envelope of `part` moved by `motion`, approximated by screws between poses sampled so that
/// no point of the part moves more than `tolerance` (> 0) between two samples; with the part at
/// the first and last poses.
ScrewSweep screw_sweep(const geometry::Mesh& part, const sweep::RelativeMotion& motion, double tolerance);

}  // namespace reconfig::cli
