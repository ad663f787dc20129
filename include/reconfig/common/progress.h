#pragma once
/// @file
/// Progress reporting and cancellation for long operations (OpenVDB-interrupter style).

#include <functional>

namespace reconfig {

/// Called by long operations with the fraction done in [0, 1]. Return `false` to cancel;
/// the operation then stops at its next check and reports that it was cancelled.
using ProgressCallback = std::function<bool(double fraction)>;

/// Calls `progress(fraction)` if set; returns whether to go on.
inline bool report_progress(const ProgressCallback& progress, double fraction) {
  return !progress || progress(fraction);
}

}  // namespace reconfig
