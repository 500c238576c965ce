// progress.hpp — progress reporting and cancellation for long work.
// A Progress wraps a callback that receives the current stage's name and the fraction of it done
// (0..1) and returns false to cancel. Work that is cancelled stops at its next check and returns a
// Cancelled error (cancelledError): cancellation is always an error, never a partial result.
// Callbacks are invoked at most ~100 times per stage, never per element.
//
// A stage made of parts hands each part a sub-range (range(begin, end)): the part reports its own
// 0..1 and the callback sees begin..end of the whole stage, so nested work (a solver's setup and its
// iterations) needs no arithmetic of its own.
#pragma once
#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

#include "straightest/base/error.hpp"

namespace straightest {

class Progress {
 public:
  using Callback = std::function<bool(const char* stage, double fraction)>;

  Progress() = default;
  Progress(Callback callback)  // NOLINT(implicit): a lambda is a Progress
      : callback_(callback ? std::make_shared<const Callback>(std::move(callback)) : nullptr) {}
  template <class F, class = std::enable_if_t<std::is_invocable_r_v<bool, F, const char*, double> &&
                                              !std::is_same_v<std::decay_t<F>, Progress> &&
                                              !std::is_same_v<std::decay_t<F>, Callback>>>
  Progress(F f) : Progress(Callback(std::move(f))) {}  // NOLINT(implicit)

  /// True when someone listens.
  explicit operator bool() const { return callback_ != nullptr; }

  /// Reports `fraction` (clamped to 0..1) of this range's work in `stage`; false means "stop".
  bool operator()(const char* stage, double fraction) const {
    if (!callback_) return true;
    const double f = std::clamp(fraction, 0.0, 1.0);
    return (*callback_)(stage, begin_ + (end_ - begin_) * f);
  }

  /// The part [begin, end] (fractions of this range) of the work: its 0..1 maps onto begin..end.
  Progress range(double begin, double end) const {
    Progress p = *this;
    p.begin_ = begin_ + (end_ - begin_) * begin;
    p.end_ = begin_ + (end_ - begin_) * end;
    return p;
  }

 private:
  std::shared_ptr<const Callback> callback_;
  double begin_ = 0, end_ = 1;
};

/// A loop's progress in one stage, passed on only when the fraction has moved by a hundredth (so at
/// most ~100 calls however many iterations); false means "stop".
class ThrottledProgress {
 public:
  ThrottledProgress(const Progress& progress, const char* stage) : progress_(progress), stage_(stage) {}
  // It keeps a reference: a temporary would be gone before the first call.
  ThrottledProgress(Progress&& progress, const char* stage) = delete;
  bool operator()(double fraction) {
    if (fraction < last_ + 0.01) return true;
    last_ = fraction;
    return progress_(stage_, fraction);
  }

 private:
  const Progress& progress_;
  const char* stage_;
  double last_ = -1;
};

/// Calls `progress`; true means "go on".
inline bool report(const Progress& progress, const char* stage, double fraction) { return progress(stage, fraction); }

/// The error every cancelled operation returns: "<what> cancelled".
inline Error cancelledError(const std::string& what) { return Error{ErrorCode::Cancelled, what + " cancelled"}; }

}  // namespace straightest
