// solve_progress.hpp — how the solver stack reports progress: every part reports as stage "solve"
// (its caller hands each part a sub-range of that stage), and an iteration measures its progress by
// the logarithm of the residual's fall from where it started to the tolerance, never going back
// (Krylov residuals are not monotone, a progress bar must be). Internal to the solver sources.
#pragma once
#include <algorithm>
#include <cmath>

#include "straightest/base/progress.hpp"

namespace straightest {

inline constexpr const char* kSolveStage = "solve";

class ResidualProgress {
 public:
  /// start: the relative residual before the first iteration; tolerance: the one that ends them.
  ResidualProgress(const Progress& progress, double start, double tolerance)
      : progress_(progress), start_(std::max(start, 2 * tolerance)), tolerance_(tolerance) {}

  /// Reports the progress at relative residual `residual`; false means "stop".
  bool operator()(double residual) {
    const double done = std::log(start_ / std::max(residual, tolerance_)) / std::log(start_ / tolerance_);
    reported_ = std::max(reported_, std::clamp(done, 0.0, 1.0));
    return progress_(kSolveStage, reported_);
  }

 private:
  const Progress& progress_;
  double start_, tolerance_, reported_ = 0;
};

}  // namespace straightest
