#pragma once
/// @file
/// A terminal progress bar for long operations (drawn on stderr only when it is a terminal).

#include <chrono>
#include <mutex>
#include <string>

#include "reconfig/common/progress.h"

namespace reconfig::cli {

class ProgressBar {
 public:
  /// @param label    what is running ("checking")
  /// @param enabled  draw at all (false for --json / --quiet or when stderr is not a terminal)
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();

  /// A callback for library calls; thread-safe, never cancels.
  ProgressCallback callback();
  void finish();

 private:
  void draw(double fraction);
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_draw_{};
};

/// Whether stderr is an interactive terminal.
bool stderr_is_terminal();

}  // namespace reconfig::cli
