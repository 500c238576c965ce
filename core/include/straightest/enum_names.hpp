// enum_names.hpp — the user-visible name of every enum value a caller types or reads, one table per
// enum. parse*/…Name functions, the CLI's usage text and errors, and the npm package's name lists
// (st.traceStatuses, st.boundaryKinds, …) all read these tables, so a name is spelled once.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "straightest/boundary_map.hpp"
#include "straightest/error.hpp"
#include "straightest/geodesic_distance.hpp"
#include "straightest/geodesic_shoot.hpp"
#include "straightest/interior_weights.hpp"
#include "straightest/mesh_io.hpp"
#include "straightest/parameterize.hpp"
#include "straightest/straightest_path.hpp"

namespace straightest {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

inline constexpr EnumName<TraceStatus> kTraceStatusNames[] = {
    {TraceStatus::Reached, "reached"},
    {TraceStatus::HitBoundary, "hit_boundary"},
    {TraceStatus::OtherComponent, "other_component"},
    {TraceStatus::Loop, "loop"},
    {TraceStatus::StepLimit, "step_limit"},
    {TraceStatus::NoExit, "no_exit"},
    {TraceStatus::DegeneratePlane, "degenerate_plane"},
};
inline constexpr EnumName<BoundaryKind> kBoundaryKindNames[] = {{BoundaryKind::Measured, "measured"},
                                                                {BoundaryKind::Circle, "circle"},
                                                                {BoundaryKind::Square, "square"},
                                                                {BoundaryKind::Free, "free"}};
inline constexpr EnumName<WeightKind> kWeightKindNames[] = {{WeightKind::ShapePreserving, "shape-preserving"},
                                                            {WeightKind::MeanValue, "mean-value"},
                                                            {WeightKind::Cotan, "cotan"},
                                                            {WeightKind::Uniform, "uniform"}};
inline constexpr EnumName<LinearSolver> kLinearSolverNames[] = {{LinearSolver::Multigrid, "multigrid"},
                                                                {LinearSolver::SparseLU, "lu"},
                                                                {LinearSolver::BiCGSTAB, "bicgstab"}};
inline constexpr EnumName<DistanceMethod> kDistanceMethodNames[] = {{DistanceMethod::Heat, "heat"},
                                                                    {DistanceMethod::Dijkstra, "dijkstra"},
                                                                    {DistanceMethod::Exact, "exact"}};
inline constexpr EnumName<ShootStatus> kShootStatusNames[] = {{ShootStatus::ReachedLength, "reached_length"},
                                                              {ShootStatus::HitBoundary, "hit_boundary"},
                                                              {ShootStatus::StepLimit, "step_limit"},
                                                              {ShootStatus::NoExit, "no_exit"}};
inline constexpr EnumName<MeshFormat> kMeshFormatNames[] = {{MeshFormat::Obj, "obj"},
                                                            {MeshFormat::Off, "off"},
                                                            {MeshFormat::Ply, "ply"},
                                                            {MeshFormat::Stl, "stl"},
                                                            {MeshFormat::Auto, "auto"}};
inline constexpr EnumName<CutMethod> kCutMethodNames[] = {{CutMethod::Disk, "disk"},
                                                          {CutMethod::Fill, "fill"},
                                                          {CutMethod::Path, "path"},
                                                          {CutMethod::CutGraph, "cut-graph"}};

/// The word that stands for "let the library choose" wherever a choice is optional (source, boundary).
inline constexpr const char* kAutoName = "auto";

template <class E, size_t N>
const char* nameOf(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& e : table)
    if (e.value == value) return e.name;
  return "unknown";
}

template <class E, size_t N>
std::optional<E> valueOf(const EnumName<E> (&table)[N], std::string_view name) {
  for (const EnumName<E>& e : table)
    if (name == e.name) return e.value;
  return std::nullopt;
}

/// Every name of the table, in its order (plus `extra`, e.g. "auto", when given).
template <class E, size_t N>
std::vector<std::string> namesOf(const EnumName<E> (&table)[N], const char* extra = nullptr) {
  std::vector<std::string> names;
  for (const EnumName<E>& e : table) names.push_back(e.name);
  if (extra) names.push_back(extra);
  return names;
}

/// "a, b or c": the choices as an error message or usage text lists them.
std::string choiceList(const std::vector<std::string>& names, const char* separator = ", ", const char* last = " or ");

/// The name → value step of every parse function: InvalidArgument "unknown <what> '<name>' (use …)".
template <class E, size_t N>
Expected<E> parseName(const EnumName<E> (&table)[N], std::string_view name, const char* what,
                      ErrorCode code = ErrorCode::InvalidArgument) {
  if (auto v = valueOf(table, name)) return *v;
  return Error{code, std::string("unknown ") + what + " '" + std::string(name) + "' (use " +
                         choiceList(namesOf(table)) + ")"};
}

}  // namespace straightest
