// straightest_path.hpp — the straightest path from a source to destinations by cutting planes.
//
// The path to D is the section of the mesh by the cutting plane (through S, perpendicular to the
// base plane, containing D), walked face by face from S toward D:
//  - start into the face around S whose section leaves on D's side (t = D − S without its base-normal
//    component); at a saddle, the one best aligned with t;
//  - cross edges; where the plane passes through a vertex (|signed distance| <= kOnPlaneRel · mean
//    edge length, decided once per vertex so neighbouring faces agree), continue from the vertex
//    into the exit best aligned with the incoming direction (excluding the face just left); an edge
//    lying in the plane is walked along;
//  - stop at D. If the walk hits the boundary, returns to S, revisits a crossing (loop) or exceeds the
//    step bound, walk the other way along the same section from S (leaving on the −t side); if neither
//    reaches D, return the first walk's status and partial path.
// Closed meshes (no boundary loop; the paper's future work): the base normal is the area-weighted
// normal at S (base_plane.hpp, reported as a fallback), and the section through S is a closed curve.
// Both directions are always walked; when both reach D the section closes through D and the shorter
// arc is returned (`reversed` says which way it leaves S: forward = toward t), the longer one's length
// as `otherArcLength`. When the walk comes back to S without meeting D, D lies on another component
// of the section (the plane cuts the surface in several closed curves): status OtherComponent, on any
// mesh (when neither walk reaches D on a closed mesh, a walk that came back to S is reported before a
// loop or step limit). S and D in one face: the straight segment, and on a closed mesh the other arc
// too. Meshes with a boundary keep the paper's rule above (the first walk that reaches D; the second
// runs only when the first fails), so they never report an other arc and cost nothing extra.
// Cost is output-sensitive: O(faces crossed) per destination, and the tracer's setup is O(faces around
// S) (plus one O(V) stamp array, allocated at the first walk through a vertex); no allocation per step
// (the point buffers are reused). Loops need no per-edge stamps: between two vertex passings the
// section is a 1-manifold, so a walk that cycles there first comes back to the piece's first crossed
// edge; vertex passings are stamped.
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "straightest/base/names.hpp"
#include "straightest/base/progress.hpp"
#include "straightest/base/timings.hpp"
#include "straightest/paths/base_plane.hpp"

namespace straightest {

enum class TraceStatus : uint8_t {
  Reached,          // the only success
  HitBoundary,      // the section left the surface before D
  OtherComponent,   // the section through S is a closed curve that misses D (D is on another of its components)
  Loop,             // the walk revisited a crossing without returning to S
  StepLimit,        // more steps than the bound
  NoExit,           // at a vertex no face continues the section (degenerate neighbourhood)
  DegeneratePlane,  // D − S parallel to the base normal, or D == S
};
/// The user-visible names (names.hpp: nameOf, parseName, namesOf).
inline constexpr EnumName<TraceStatus> kTraceStatusNames[] = {
    {TraceStatus::Reached, "reached"},
    {TraceStatus::HitBoundary, "hit_boundary"},
    {TraceStatus::OtherComponent, "other_component"},
    {TraceStatus::Loop, "loop"},
    {TraceStatus::StepLimit, "step_limit"},
    {TraceStatus::NoExit, "no_exit"},
    {TraceStatus::DegeneratePlane, "degenerate_plane"},
};
const char* traceStatusName(TraceStatus s);
inline constexpr int kTraceStatusCount = 7;

struct TraceOptions {
  bool keepPoints = true;      // store the path's surface points and positions
  int64_t maxSteps = 0;        // 0: 2·faces + vertices + 16 (more than any simple walk can take)
  Timings* timings = nullptr;  // batch: receives "prepare" (base plane, tables) and "trace" (all walks)
};

struct StraightestPath {
  TraceStatus status = TraceStatus::NoExit;
  double length = 0;         // sum of segment lengths (of the partial path when not reached)
  int64_t facesCrossed = 0;  // segments walked (each lies in one face or along one edge)
  bool reversed = false;     // reached by the second walk (leaving on the −t side): "backward"
  double otherArcLength = std::numeric_limits<double>::quiet_NaN();  // the other way's length to D, when both reach
  std::vector<SurfacePoint> points;                                  // S, crossings..., D (when keepPoints)
  std::vector<Vec3> positions;                                       // their 3D positions
  std::vector<Vec3> otherPositions;  // the other arc's 3D positions S..D, when both reach (and keepPoints)
};

/// Traces straightest paths from one source; reuse it for many destinations (shared setup).
class StraightestPathTracer {
 public:
  /// The source must be a valid surface point (see validateSurfacePoint). It is moved onto an edge or
  /// vertex within kSnapSource (barycentric or edge parameter): source() is canonical(mesh, source,
  /// kSnapSource), the point used. (Leaving a point 1e-9 away from an edge, the walk's first crossing
  /// would be closer than its on-segment tolerance and could be missed.)
  StraightestPathTracer(const TriMesh& mesh, const SurfacePoint& source, const TraceOptions& options = {});
  ~StraightestPathTracer();
  StraightestPathTracer(StraightestPathTracer&&) noexcept;
  StraightestPathTracer& operator=(StraightestPathTracer&&) noexcept;

  const BasePlane& base() const;
  const SurfacePoint& source() const;

  /// Traces to one destination (a valid surface point). The returned reference stays valid until
  /// the next call (its buffers are reused).
  const StraightestPath& trace(const SurfacePoint& destination);

 private:
  struct Impl;  // the setup around the source and the walk's buffers (straightest_path.cpp)
  std::unique_ptr<Impl> impl_;
};

/// Many destinations from one source in one call (shared setup), results packed for transport:
/// path i's points are points[offsets[i] .. offsets[i+1]) (when keepPoints).
struct PathBatch {
  SurfacePoint source;
  BasePlane base;
  std::vector<SurfacePoint> targets;
  std::vector<Vec3> targetPositions;
  std::vector<TraceStatus> status;
  std::vector<double> length;
  std::vector<int64_t> facesCrossed;
  std::vector<uint8_t> reversed;
  std::vector<double> otherArcLength;  // NaN unless both directions reach the target
  std::vector<Vec3> directions;        // per target: inPlaneDirection toward it (NaN × 3 where undefined)
  std::vector<Vec3> points;
  std::vector<int64_t> offsets;
  std::vector<Vec3> otherPoints;      // the other arcs (empty ones where there is none), when keepPoints
  std::vector<int64_t> otherOffsets;  // path i's other arc is otherPoints[otherOffsets[i] .. otherOffsets[i+1])
};

/// The vertices of the longest boundary loop, in order (empty for a closed mesh).
std::vector<SurfacePoint> boundaryTargets(const TriMesh& mesh);

/// A destination as callers name it: a surface point, every vertex of the longest boundary loop
/// ("boundary"), or every vertex of every loop, longest loop first ("all-boundaries").
struct BoundaryVertices {};
struct AllBoundaryVertices {};
using TargetSpec = std::variant<SurfacePoint, BoundaryVertices, AllBoundaryVertices>;

/// The targets in order, each point validated (an error names "target i"), each BoundaryVertices
/// expanded into boundaryTargets and each AllBoundaryVertices into every loop's vertices (a Topology
/// error on a closed mesh: "the mesh is closed (no boundary loop): name the targets").
Expected<std::vector<SurfacePoint>> resolveTargets(const TriMesh& mesh, const std::vector<TargetSpec>& specs);

/// What a batch amounts to: the CLI's "summary" and the npm result's counts.
struct PathSummary {
  int64_t paths = 0, reached = 0;
  std::vector<int64_t> byStatus;  // count per TraceStatus (kTraceStatusCount entries)
  double meanLength = 0;          // over reached paths (0 when none)
  double maxLength = 0;           // over reached paths
  int64_t facesCrossed = 0;       // over all paths
  int64_t maxFacesCrossed = 0;    // the longest walk, in faces (any status)
  int64_t otherArcs = 0;          // paths that also reached D the other way round (closed meshes)
};
PathSummary summarize(const PathBatch& batch);

/// Traces every target (each a valid surface point; see validateSurfacePoint). Progress stage: "trace";
/// cancelling returns a Cancelled error (never a partial batch).
Expected<PathBatch> traceStraightestPaths(const TriMesh& mesh, const SurfacePoint& source,
                                          std::vector<SurfacePoint> targets, const TraceOptions& options = {},
                                          const Progress& progress = {});

}  // namespace straightest
