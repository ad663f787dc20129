#pragma once
/// @file
/// Ctrl+C during a long command: recorded instead of killing the process, so the operation
/// stops at its next progress report and the tool says so and exits with code 130.

#include "reconfig/common/progress.h"

namespace reconfig::cli {

class InterruptGuard {
 public:
  /// Catches SIGINT once (a second Ctrl+C kills the process as usual).
  InterruptGuard();
  /// Restores what SIGINT did before.
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Whether Ctrl+C was pressed while the guard was alive.
  bool interrupted() const;
  /// `inner` (may be empty), returning false once Ctrl+C was pressed: the operation cancels.
  ProgressCallback wrap(ProgressCallback inner) const;
};

}  // namespace reconfig::cli
