// The many-target side of straightest_path.hpp: target lists ("boundary", "all-boundaries", points),
// the batch of paths from one source traced on all threads (one tracer per thread, chunks of targets,
// points joined in target order so the batch is the same for any thread count), and its summary. The
// walk itself is in straightest_path.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <variant>

#include "straightest/base/parallel_for.hpp"
#include "straightest/base/timings.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {

std::vector<SurfacePoint> boundaryTargets(const TriMesh& mesh) {
  std::vector<SurfacePoint> targets;
  if (mesh.boundaryLoops().empty()) return targets;
  for (int32_t v : mesh.boundaryLoops()[0]) targets.push_back(SurfacePoint::vertex(v));
  return targets;
}

Expected<std::vector<SurfacePoint>> resolveTargets(const TriMesh& mesh, const std::vector<TargetSpec>& specs) {
  std::vector<SurfacePoint> targets;
  for (size_t i = 0; i < specs.size(); ++i) {
    const bool one = std::holds_alternative<BoundaryVertices>(specs[i]);
    if (one || std::holds_alternative<AllBoundaryVertices>(specs[i])) {
      const char* name = one ? "boundary" : "all-boundaries";
      if (mesh.boundaryLoops().empty())
        return Error{ErrorCode::Topology,
                     std::string("targets '") + name + "': the mesh is closed (no boundary loop): name the targets"};
      for (const auto& loop : mesh.boundaryLoops()) {  // longest first
        for (int32_t v : loop) targets.push_back(SurfacePoint::vertex(v));
        if (one) break;
      }
      continue;
    }
    auto p = validateSurfacePoint(mesh, std::get<SurfacePoint>(specs[i]));
    if (!p) return Error{p.error().code, "target " + std::to_string(i) + ": " + p.error().message};
    targets.push_back(p.value());
  }
  return targets;
}

PathSummary summarize(const PathBatch& batch) {
  PathSummary s;
  s.paths = static_cast<int64_t>(batch.status.size());
  s.byStatus.assign(kTraceStatusCount, 0);
  double sum = 0;
  for (size_t i = 0; i < batch.status.size(); ++i) {
    ++s.byStatus[static_cast<size_t>(batch.status[i])];
    s.facesCrossed += batch.facesCrossed[i];
    s.maxFacesCrossed = std::max(s.maxFacesCrossed, batch.facesCrossed[i]);
    if (!std::isnan(batch.otherArcLength[i])) ++s.otherArcs;
    if (batch.status[i] != TraceStatus::Reached) continue;
    ++s.reached;
    sum += batch.length[i];
    s.maxLength = std::max(s.maxLength, batch.length[i]);
  }
  s.meanLength = s.reached > 0 ? sum / static_cast<double>(s.reached) : 0.0;
  return s;
}

namespace {

/// The per-target columns of a batch of n paths, sized (filled in place by the threads).
void sizeColumns(PathBatch& batch, size_t n) {
  batch.targetPositions.resize(n);
  batch.status.resize(n);
  batch.length.resize(n);
  batch.facesCrossed.resize(n);
  batch.reversed.resize(n);
  batch.otherArcLength.resize(n);
  batch.directions.resize(n);
}

/// The chunks' points joined in target order, with each target's offset (counts: points per target).
void joinChunks(std::vector<std::vector<Vec3>>& parts, const std::vector<int64_t>& counts, std::vector<Vec3>& points,
                std::vector<int64_t>& offsets) {
  const size_t n = counts.size();
  offsets.resize(n + 1);
  offsets[0] = 0;
  for (size_t i = 0; i < n; ++i) offsets[i + 1] = offsets[i] + counts[i];
  points.reserve(static_cast<size_t>(offsets[n]));
  for (std::vector<Vec3>& part : parts) {
    points.insert(points.end(), part.begin(), part.end());
    std::vector<Vec3>().swap(part);
  }
}

}  // namespace

Expected<PathBatch> traceStraightestPaths(const TriMesh& mesh, const SurfacePoint& source,
                                          std::vector<SurfacePoint> targets, const TraceOptions& options,
                                          const Progress& progress) {
  Stopwatch time;
  PathBatch batch;
  // A tracer keeps per-walk state: each thread takes its own from this stack (a walk's result does not
  // depend on the walks its tracer made before), so at most threadCount() tracers ever exist.
  std::mutex idleMutex;
  std::vector<std::unique_ptr<StraightestPathTracer>> idle;
  idle.push_back(std::make_unique<StraightestPathTracer>(mesh, source, options));
  batch.source = source;
  batch.base = idle.back()->base();
  batch.targets = std::move(targets);
  const size_t n = batch.targets.size();
  sizeColumns(batch, n);
  // Targets in chunks: the per-target values go straight to their slots; the points of each chunk to
  // its own buffer, joined in target order at the end (the batch is the same for any thread count).
  // A chunk is a run of neighbouring targets, whose paths cross nearly the same faces: the longer the
  // runs a thread walks, the more of the mesh it finds in its own caches. About 16 chunks (at least 8
  // targets each; at most 1024, so that progress moves and a cancel is
  // heard) keep the threads' shares even; runs of a few targets each were much slower, and from about
  // 16 chunks down the count hardly mattered (docs/BENCHMARKS.md).
  const size_t targetsPerChunk = std::clamp<size_t>((n + 15) / 16, 8, 1024);
  const size_t chunks = detail::chunkCount(n, targetsPerChunk);
  std::vector<std::vector<Vec3>> chunkPoints(chunks), chunkOtherPoints(chunks);
  std::vector<int64_t> pointCount(n), otherPointCount(n);
  record(options.timings, "prepare", time.lap());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto traceChunk = [&](size_t chunk, size_t begin, size_t end) {
    std::unique_ptr<StraightestPathTracer> tracer;
    {
      std::lock_guard<std::mutex> lock(idleMutex);
      if (!idle.empty()) {
        tracer = std::move(idle.back());
        idle.pop_back();
      }
    }
    if (!tracer) tracer = std::make_unique<StraightestPathTracer>(mesh, source, options);
    for (size_t i = begin; i < end; ++i) {
      const StraightestPath& path = tracer->trace(batch.targets[i]);
      batch.status[i] = path.status;
      batch.length[i] = path.length;
      batch.facesCrossed[i] = path.facesCrossed;
      batch.reversed[i] = path.reversed;
      batch.otherArcLength[i] = path.otherArcLength;
      const Vec3 D = position(mesh, batch.targets[i]);
      batch.targetPositions[i] = D;
      const auto direction = inPlaneDirection(batch.base, D);
      batch.directions[i] = direction ? *direction : Vec3{nan, nan, nan};
      chunkPoints[chunk].insert(chunkPoints[chunk].end(), path.positions.begin(), path.positions.end());
      pointCount[i] = static_cast<int64_t>(path.positions.size());
      chunkOtherPoints[chunk].insert(chunkOtherPoints[chunk].end(), path.otherPositions.begin(),
                                     path.otherPositions.end());
      otherPointCount[i] = static_cast<int64_t>(path.otherPositions.size());
    }
    std::lock_guard<std::mutex> lock(idleMutex);
    idle.push_back(std::move(tracer));
  };
  if (!detail::parallelFor(n, targetsPerChunk, traceChunk, progress, "trace"))
    return cancelledError("straightest paths");
  joinChunks(chunkPoints, pointCount, batch.points, batch.offsets);
  joinChunks(chunkOtherPoints, otherPointCount, batch.otherPoints, batch.otherOffsets);
  record(options.timings, "trace", time.lap());
  return batch;
}

}  // namespace straightest
