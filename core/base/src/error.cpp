// error.cpp — the error codes' user-visible names, numbers as messages write them, and the one mapping of a
// caught exception to an Error.
#include "straightest/base/error.hpp"

#include <cstdio>
#include <exception>
#include <new>

namespace straightest {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::Io: return "io";
    case ErrorCode::UnsupportedFormat: return "unsupported_format";
    case ErrorCode::Parse: return "parse";
    case ErrorCode::Empty: return "empty";
    case ErrorCode::TooLarge: return "too_large";
    case ErrorCode::NonFinite: return "non_finite";
    case ErrorCode::IndexOutOfRange: return "index_out_of_range";
    case ErrorCode::InvalidFace: return "invalid_face";
    case ErrorCode::DuplicateFace: return "duplicate_face";
    case ErrorCode::Degenerate: return "degenerate";
    case ErrorCode::NonManifoldEdge: return "non_manifold_edge";
    case ErrorCode::NonManifoldVertex: return "non_manifold_vertex";
    case ErrorCode::NonOrientable: return "non_orientable";
    case ErrorCode::Topology: return "topology";
    case ErrorCode::InvalidArgument: return "invalid_argument";
    case ErrorCode::Cancelled: return "cancelled";
    case ErrorCode::Internal: return "internal";
  }
  return "unknown";
}

std::vector<std::string> errorCodeNames() {
  std::vector<std::string> names;
  for (int c = 0; c <= static_cast<int>(ErrorCode::Internal); ++c)
    names.push_back(errorCodeName(static_cast<ErrorCode>(c)));
  return names;
}

std::string numberText(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

Error errorFromCurrentException() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    return Error{ErrorCode::TooLarge, "the mesh is too large for the available memory (an allocation failed)"};
  } catch (const std::exception& e) {
    return Error{ErrorCode::Internal, std::string("internal error: ") + e.what()};
  } catch (...) {
    return Error{ErrorCode::Internal, "internal error: an unknown exception"};
  }
}

}  // namespace straightest
