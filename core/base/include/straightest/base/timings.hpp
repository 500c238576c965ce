// timings.hpp — where the time went, kept out of the result structs: a caller that wants timings
// passes a Timings in the options and the work records its stages into it (milliseconds, summed per
// stage name, in first-recorded order); a caller that does not passes nothing and pays nothing.
#pragma once
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace straightest {

class Timings {
 public:
  /// Adds ms to `stage` (a new stage goes last).
  void add(const std::string& stage, double ms) {
    for (auto& [name, total] : stages_)
      if (name == stage) {
        total += ms;
        return;
      }
    stages_.emplace_back(stage, ms);
  }
  /// Milliseconds recorded under `stage` (0 when none).
  double operator[](const std::string& stage) const {
    for (const auto& [name, total] : stages_)
      if (name == stage) return total;
    return 0;
  }
  const std::vector<std::pair<std::string, double>>& stages() const { return stages_; }

 private:
  std::vector<std::pair<std::string, double>> stages_;
};

/// Milliseconds since construction (or the last lap()).
class Stopwatch {
 public:
  double ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }
  /// ms(), and restarts.
  double lap() {
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return elapsed;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
};

/// Records into `timings` when there is one.
inline void record(Timings* timings, const std::string& stage, double ms) {
  if (timings) timings->add(stage, ms);
}

}  // namespace straightest
