// progress.hpp — progress reporting and cancellation for long work.
// A Progress callback receives the current stage's name and the fraction of it done (0..1); it returns
// false to cancel, and the work then stops at its next check and returns a Cancelled error (or a
// result marked cancelled). Callbacks are invoked at most ~100 times per stage, never per element.
#pragma once
#include <functional>

namespace straightest {

using Progress = std::function<bool(const char* stage, double fraction)>;

/// Calls `progress` if set; true means "go on".
inline bool report(const Progress& progress, const char* stage, double fraction) {
  return !progress || progress(stage, fraction);
}

}  // namespace straightest
