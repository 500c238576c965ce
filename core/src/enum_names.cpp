// The name and parse functions of every enum, all reading the tables of enum_names.hpp.
#include "straightest/enum_names.hpp"

namespace straightest {

std::string choiceList(const std::vector<std::string>& names, const char* separator, const char* last) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? last : separator;
    out += names[i];
  }
  return out;
}

}  // namespace straightest

namespace straightest {

const char* traceStatusName(TraceStatus s) { return nameOf(kTraceStatusNames, s); }
const char* boundaryKindName(BoundaryKind k) { return nameOf(kBoundaryKindNames, k); }
const char* weightKindName(WeightKind k) { return nameOf(kWeightKindNames, k); }
const char* cutMethodName(CutMethod m) { return nameOf(kCutMethodNames, m); }

Expected<WeightKind> parseWeightKind(const std::string& name) { return parseName(kWeightKindNames, name, "weights"); }
Expected<LinearSolver> parseLinearSolver(const std::string& name) {
  return parseName(kLinearSolverNames, name, "solver");
}

Expected<std::optional<BoundaryKind>> parseBoundaryChoice(const std::string& name) {
  if (name == kAutoName) return std::optional<BoundaryKind>();
  if (auto kind = valueOf(kBoundaryKindNames, name)) return std::optional<BoundaryKind>(*kind);
  return Error{ErrorCode::InvalidArgument,
               "unknown boundary '" + name + "' (use " + choiceList(namesOf(kBoundaryKindNames, kAutoName)) + ")"};
}

}  // namespace straightest
