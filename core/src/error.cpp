#include "straightest/error.hpp"

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
  }
  return "unknown";
}

}  // namespace straightest
