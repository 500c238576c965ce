// error.hpp — typed errors for bad input and a minimal Expected<T> to return them.
// Bad input (a malformed file, a mesh with the wrong topology, an unknown option) is an ordinary
// result, not an exception: every fallible entry point returns Expected<T>, whose error carries a
// category (stable, machine-readable; the CLI maps every category to exit code 2) and a message that
// says what was found and where (line, face, vertex). Exceptions are reserved for programmer errors.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace straightest {

enum class ErrorCode {
  Io,                 // file cannot be read
  UnsupportedFormat,  // neither OBJ nor OFF, or an unknown format name
  Parse,              // syntax error: bad token, bad header, truncated file, line too long
  Empty,              // no vertices or no faces
  TooLarge,           // over the configured caps (or a header claims more than the file can hold)
  NonFinite,          // NaN or Inf coordinate, or one so large (> 1e50) that products overflow
  IndexOutOfRange,    // face refers to a vertex that does not exist (or index 0 in OBJ)
  InvalidFace,        // fewer than 3 vertices, or a vertex repeated inside one face
  DuplicateFace,      // two faces with the same vertex set
  Degenerate,         // every face has zero area: nothing can be measured on it
  NonManifoldEdge,    // an edge shared by more than two faces
  NonManifoldVertex,  // a vertex whose faces form more than one fan
  NonOrientable,      // e.g. a Möbius strip: no consistent orientation exists
  Topology,           // the algorithm needs another topology (disk, boundary, ...)
  InvalidArgument,    // an option or index given by the caller is wrong
  Cancelled,          // a progress callback asked to stop
  Internal,           // a bug: an unexpected exception (the CLI exits 1 for it, 2 for every other code)
};

/// Stable snake_case name of a category ("non_manifold_edge"); used in JSON and JS errors.
const char* errorCodeName(ErrorCode code);

/// Every category name, in ErrorCode order (the npm package's ErrorCategory type lists the same).
std::vector<std::string> errorCodeNames();

struct Error {
  ErrorCode code;
  std::string message;
};

/// Either a value or an Error. Deliberately small: value(), error(), ok().
template <class T>
class Expected {
 public:
  Expected(T value) : v_(std::move(value)) {}      // NOLINT(implicit)
  Expected(Error error) : v_(std::move(error)) {}  // NOLINT(implicit)
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  const Error& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, Error> v_;
};

/// Success or an Error, for work whose result is what it did: `return {};` on success.
template <>
class Expected<void> {
 public:
  Expected() = default;
  Expected(Error error) : error_(std::move(error)) {}  // NOLINT(implicit)
  bool ok() const { return !error_; }
  explicit operator bool() const { return ok(); }
  const Error& error() const { return *error_; }

 private:
  std::optional<Error> error_;
};

/// A number as an error message shows it: six significant digits at most, no trailing zeros ("0.5", "2",
/// "1e+300", "inf", "nan"), where std::to_string would write "0.500000" or three hundred digits.
std::string numberText(double x);

/// The error for the exception being handled (call inside a catch block): allocation failure is
/// TooLarge ("… too large for the available memory"), anything else Internal. The CLI and the
/// bindings both end their work in this one mapping.
Error errorFromCurrentException();

/// Runs fn (returning Expected<T>) and turns an escaping exception into errorFromCurrentException().
template <class Fn>
auto guarded(Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (...) {
    return errorFromCurrentException();
  }
}

}  // namespace straightest
