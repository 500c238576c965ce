// The threaded loops (threads.hpp): traces to many targets, interior weights, stretch metrics and a
// whole parameterization give bit-identical results with 1, 2 and 4 threads; progress is monotone and
// reported on the calling thread only; a cancelled threaded trace returns Cancelled and leaves the pool
// usable; runAlongside runs one background task beside the caller, and a load's warm-up built on it
// changes nothing.
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "straightest/base/parallel_for.hpp"

#include "straightest/api/warm_up.hpp"
#include "straightest/base/threads.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/interior_weights.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/param/texture_stretch.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {
namespace {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
constexpr bool kThreads = false;  // a WebAssembly build without pthreads: always one thread
#else
constexpr bool kThreads = true;
#endif

/// Sets the process-wide thread count for one scope, then restores the default.
struct ThreadCountScope {
  explicit ThreadCountScope(int count) { setThreadCount(count); }
  ~ThreadCountScope() { setThreadCount(0); }
};

/// Equal bit for bit (NaN included, which == would call different).
template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Runs `compute` with 1, 2 and 4 threads and checks every result against the first with `same`.
template <class Compute, class Same>
void expectSameForThreadCounts(Compute compute, Same same) {
  std::vector<decltype(compute())> results;
  for (int threads : {1, 2, 4}) {
    const ThreadCountScope scope(threads);
    results.push_back(compute());
  }
  for (size_t k = 1; k < results.size(); ++k) same(results[0], results[k]);
}

void expectSameBatch(const PathBatch& a, const PathBatch& b) {
  EXPECT_TRUE(sameBits(a.targetPositions, b.targetPositions));
  EXPECT_TRUE(sameBits(a.status, b.status));
  EXPECT_TRUE(sameBits(a.length, b.length));
  EXPECT_TRUE(sameBits(a.facesCrossed, b.facesCrossed));
  EXPECT_TRUE(sameBits(a.reversed, b.reversed));
  EXPECT_TRUE(sameBits(a.otherArcLength, b.otherArcLength));
  EXPECT_TRUE(sameBits(a.directions, b.directions));
  EXPECT_TRUE(sameBits(a.points, b.points));
  EXPECT_TRUE(sameBits(a.offsets, b.offsets));
  EXPECT_TRUE(sameBits(a.otherPoints, b.otherPoints));
  EXPECT_TRUE(sameBits(a.otherOffsets, b.otherOffsets));
}

PathBatch traceAll(const TriMesh& mesh, std::vector<TargetSpec> specs, bool keepPoints, const Progress& progress = {}) {
  const SurfacePoint source = SurfacePoint::vertex(defaultSource(mesh).value());
  auto targets = resolveTargets(mesh, specs);
  EXPECT_TRUE(targets.ok());
  auto batch = traceStraightestPaths(mesh, source, targets.value(), TraceOptions{keepPoints}, progress);
  EXPECT_TRUE(batch.ok());
  return batch ? std::move(batch).value() : PathBatch{};
}

TEST(Threads, CountIsProcessWideWithZeroForEveryCore) {
  const ThreadCountScope scope(3);
  EXPECT_EQ(threadCount(), kThreads ? 3 : 1);
  setThreadCount(0);
  EXPECT_EQ(threadCount(), hardwareThreads());
  setThreadCount(-5);
  EXPECT_EQ(threadCount(), hardwareThreads());
  setThreadCount(1000);
  EXPECT_EQ(threadCount(), kThreads ? 64 : 1);
  EXPECT_GE(hardwareThreads(), 1);
  if (!kThreads) {
    EXPECT_EQ(hardwareThreads(), 1);
  }
}

TEST(Threads, ParallelForRunsEveryChunkOnceWithItsOwnRange) {
  for (int threads : {1, 2, 4}) {
    const ThreadCountScope scope(threads);
    const size_t count = 1003, grain = 10;  // 101 chunks, the last one of 3
    std::vector<int> runs(detail::chunkCount(count, grain), 0);
    std::vector<int> covered(count, 0);
    const bool done = detail::parallelFor(count, grain, [&](size_t chunk, size_t begin, size_t end) {
      ++runs[chunk];
      EXPECT_EQ(begin, chunk * grain);
      EXPECT_EQ(end, std::min(count, begin + grain));
      for (size_t i = begin; i < end; ++i) ++covered[i];
    });
    EXPECT_TRUE(done);
    EXPECT_EQ(runs, std::vector<int>(runs.size(), 1));
    EXPECT_EQ(covered, std::vector<int>(count, 1));
    EXPECT_TRUE(detail::parallelFor(0, grain, [](size_t, size_t, size_t) { ADD_FAILURE(); }));
  }
}

TEST(Threads, NestedLoopsRunAndExceptionsReachTheCaller) {
  const ThreadCountScope scope(kThreads ? 3 : 1);
  // A loop inside a chunk (on a worker or on the calling thread) runs serially there.
  std::vector<long> sums(40, 0);
  detail::parallelFor(sums.size(), 1, [&](size_t chunk, size_t, size_t) {
    detail::parallelFor(100, 7, [&](size_t, size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) sums[chunk] += static_cast<long>(i);
    });
  });
  EXPECT_EQ(sums, std::vector<long>(sums.size(), 4950));
  // A chunk that throws: the exception comes out of parallelFor on the calling thread, and the pool
  // runs the next loop in full.
  std::atomic<int> ran{0};
  EXPECT_THROW(detail::parallelFor(64, 1,
                                   [&](size_t chunk, size_t, size_t) {
                                     ++ran;
                                     if (chunk == 5) throw std::runtime_error("chunk 5");
                                   }),
               std::runtime_error);
  EXPECT_GE(ran.load(), 6);
  ran = 0;
  EXPECT_TRUE(detail::parallelFor(64, 1, [&](size_t, size_t, size_t) { ++ran; }));
  EXPECT_EQ(ran.load(), 64);
}

TEST(Threads, PathBatchesAreBitIdentical) {
  // All boundaries of a relief with holes (several loops), the whole boundary of a saddle with points,
  // and every vertex of a closed sphere (both arcs walked, other arcs kept).
  const TriMesh holes = makeSample("holes").value();
  const TriMesh saddle = makeSample("saddle").value();
  const TriMesh sphere = makeSample("sphere").value();
  const TriMesh relief = makeHeightField(150);
  std::vector<TargetSpec> everyVertex;
  for (int32_t v = 0; v < sphere.numVertices(); ++v) everyVertex.push_back(SurfacePoint::vertex(v));
  struct Case {
    const TriMesh* mesh;
    std::vector<TargetSpec> targets;
    bool keepPoints;
  };
  const std::vector<Case> cases = {{&holes, {AllBoundaryVertices{}}, true},
                                   {&saddle, {BoundaryVertices{}}, true},
                                   {&relief, {AllBoundaryVertices{}}, false},
                                   {&sphere, everyVertex, true}};
  for (const Case& c : cases) {
    expectSameForThreadCounts([&] { return traceAll(*c.mesh, c.targets, c.keepPoints); },
                              [](const PathBatch& a, const PathBatch& b) { expectSameBatch(a, b); });
  }
  // Not vacuous: the relief's traces reach their targets, over many chunks of targets.
  const PathBatch batch = traceAll(relief, {AllBoundaryVertices{}}, false);
  EXPECT_GT(batch.status.size(), 500u);
  EXPECT_EQ(summarize(batch).reached, static_cast<int64_t>(batch.status.size()));
}

TEST(Threads, InteriorWeightsAreBitIdentical) {
  const TriMesh mesh = makeHeightField(150);  // 22500 vertices: several chunks of rows
  for (WeightKind kind : {WeightKind::Uniform, WeightKind::ShapePreserving, WeightKind::MeanValue, WeightKind::Cotan}) {
    expectSameForThreadCounts([&] { return interiorWeights(mesh, kind); },
                              [](const InteriorWeights& a, const InteriorWeights& b) {
                                EXPECT_TRUE(sameBits(a.rows, b.rows));
                                EXPECT_TRUE(sameBits(a.weights.start, b.weights.start));
                                EXPECT_TRUE(sameBits(a.weights.col, b.weights.col));
                                EXPECT_TRUE(sameBits(a.weights.value, b.weights.value));
                                EXPECT_EQ(a.uniformFallbacks, b.uniformFallbacks);
                              });
  }
  // Each row is a convex combination of the vertex's ring (shape-preserving weights on a relief).
  const InteriorWeights W = interiorWeights(mesh, WeightKind::ShapePreserving);
  EXPECT_EQ(W.weights.rows, static_cast<int32_t>(W.rows.size()));
  for (int32_t r = 0; r < W.weights.rows; ++r) {
    double sum = 0;
    for (int32_t k = W.weights.start[r]; k < W.weights.start[r + 1]; ++k) sum += W.weights.value[k];
    ASSERT_NEAR(sum, 1, 1e-12);
  }
}

TEST(Threads, StretchMetricsAreBitIdentical) {
  const TriMesh mesh = makeHeightField(150);  // 44402 faces: several chunks of faces
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.positions()) uv.push_back({p.x + 0.3 * p.y * p.y, p.y});  // sheared, not isometric
  std::vector<Vec2> folded = uv;
  folded[mesh.numVertices() / 2 + 10] = {-5, -5};  // folds a few faces
  for (const auto* map : {&uv, &folded}) {
    expectSameForThreadCounts([&] { return textureStretch(mesh, *map); },
                              [](const StretchMetrics& a, const StretchMetrics& b) {
                                EXPECT_TRUE(sameBits(a.l2, b.l2));
                                EXPECT_TRUE(sameBits(a.linf, b.linf));
                                EXPECT_TRUE(sameBits(a.areaDistortionMean, b.areaDistortionMean));
                                EXPECT_TRUE(sameBits(a.areaDistortionMax, b.areaDistortionMax));
                                EXPECT_TRUE(sameBits(a.angleDistortionMean, b.angleDistortionMean));
                                EXPECT_TRUE(sameBits(a.angleDistortionMax, b.angleDistortionMax));
                                EXPECT_EQ(a.flipped, b.flipped);
                                EXPECT_EQ(a.degenerate, b.degenerate);
                                EXPECT_EQ(a.overlaps, b.overlaps);
                                EXPECT_TRUE(sameBits(a.faceStretch, b.faceStretch));
                              });
  }
  EXPECT_TRUE(textureStretch(mesh, uv).bijective);
  EXPECT_GT(textureStretch(mesh, folded).flipped, 0);
}

TEST(Threads, WholeParameterizationsAreBitIdentical) {
  const TriMesh relief = makeHeightField(120);
  const TriMesh saddle = makeSample("saddle").value();
  auto same = [](const Parameterization& a, const Parameterization& b) {
    EXPECT_TRUE(sameBits(a.uv, b.uv));
    EXPECT_TRUE(sameBits(a.boundaryPolygon, b.boundaryPolygon));
    EXPECT_TRUE(sameBits(a.metrics.l2, b.metrics.l2));
    EXPECT_TRUE(sameBits(a.metrics.faceStretch, b.metrics.faceStretch));
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.boundary, b.boundary);
  };
  // The relief measured; the saddle with auto (four maps solved and the free one refined).
  const std::vector<std::pair<const TriMesh*, std::optional<BoundaryKind>>> cases = {{&relief, BoundaryKind::Measured},
                                                                                     {&saddle, std::nullopt}};
  for (const auto& c : cases) {
    const TriMesh& mesh = *c.first;
    ParamOptions options;
    options.boundary = c.second;
    expectSameForThreadCounts(
        [&] {
          auto p = parameterize(mesh, options);
          EXPECT_TRUE(p.ok());
          EXPECT_TRUE(p && p.value().metrics.bijective);
          return p ? std::move(p).value() : Parameterization{};
        },
        same);
  }
}

TEST(Threads, ProgressIsMonotoneAndOnTheCallingThread) {
  const TriMesh mesh = makeHeightField(200);  // 796 targets: 25 chunks
  for (int threads : {1, 2, 4}) {
    const ThreadCountScope scope(threads);
    std::mutex mutex;  // only needed if the contract were broken (a call from another thread)
    std::vector<std::pair<std::thread::id, double>> calls;
    const Progress progress([&](const char*, double fraction) {
      std::lock_guard<std::mutex> lock(mutex);
      calls.emplace_back(std::this_thread::get_id(), fraction);
      return true;
    });
    traceAll(mesh, {AllBoundaryVertices{}}, false, progress);
    ASSERT_GE(calls.size(), 2u);  // the start and the end at least
    EXPECT_EQ(calls.front().second, 0.0);
    EXPECT_EQ(calls.back().second, 1.0);
    for (size_t k = 0; k < calls.size(); ++k) {
      EXPECT_EQ(calls[k].first, std::this_thread::get_id());
      if (k > 0) {
        EXPECT_GE(calls[k].second, calls[k - 1].second);
      }
    }
  }
}

TEST(Threads, CancelledThreadedTraceLeavesThePoolUsable) {
  const TriMesh mesh = makeHeightField(200);
  const PathBatch reference = [&] {
    const ThreadCountScope scope(1);
    return traceAll(mesh, {AllBoundaryVertices{}}, true);
  }();
  const ThreadCountScope scope(kThreads ? 4 : 1);
  const SurfacePoint source = SurfacePoint::vertex(defaultSource(mesh).value());
  const auto targets = resolveTargets(mesh, {AllBoundaryVertices{}}).value();
  // Before any chunk, then at the next call: while chunks run, or at the end when the other threads
  // took every chunk meanwhile (a cancel at 1.0 is a cancel too).
  for (int cancelAtCall : {1, 2}) {
    int calls = 0;
    const Progress cancel([&](const char*, double) { return ++calls < cancelAtCall; });
    const auto cancelled = traceStraightestPaths(mesh, source, targets, TraceOptions{}, cancel);
    SCOPED_TRACE(::testing::Message() << "cancel at call " << cancelAtCall << ", calls " << calls);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error().code, ErrorCode::Cancelled);
    // The pool runs the next batch in full, as a single thread would.
    expectSameBatch(reference, traceAll(mesh, {AllBoundaryVertices{}}, true));
  }
}

TEST(Threads, CancelFromAnotherThreadStopsAThreadedTrace) {
  if (!kThreads) GTEST_SKIP() << "no second thread in a WebAssembly build without pthreads";
  const TriMesh mesh = makeHeightField(200);
  const ThreadCountScope scope(kThreads ? 2 : 1);
  const SurfacePoint source = SurfacePoint::vertex(defaultSource(mesh).value());
  const auto targets = resolveTargets(mesh, {AllBoundaryVertices{}}).value();
  // A user's cancel button: another thread sets the flag that the progress callback reads. The callback
  // waits, once chunks are running (its second call), until that thread has pressed it.
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  std::condition_variable pressed;
  int calls = 0;
  std::thread button([&] {
    std::lock_guard<std::mutex> lock(mutex);
    cancel = true;
    pressed.notify_all();
  });
  const Progress progress([&](const char*, double) {
    if (++calls == 2) {
      std::unique_lock<std::mutex> lock(mutex);
      pressed.wait(lock, [&] { return cancel.load(); });
    }
    return !cancel.load() || calls < 2;
  });
  const auto batch = traceStraightestPaths(mesh, source, targets, TraceOptions{false}, progress);
  button.join();
  ASSERT_FALSE(batch.ok());
  EXPECT_EQ(batch.error().code, ErrorCode::Cancelled);
  EXPECT_EQ(calls, 2);  // no call after the one that said stop
}

/// runAlongside: background(stop) on a pool worker while the caller runs foreground.
TEST(Threads, RunAlongsideRunsTheBackgroundOnAWorkerUntilTheForegroundReturns) {
  if (!kThreads) GTEST_SKIP() << "no threads in this build";
  ThreadCountScope scope(2);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> started{false}, sawStop{false}, returned{false};
  std::thread::id backgroundThread;
  detail::runAlongside(
      [&](const std::atomic<bool>& stop) {
        backgroundThread = std::this_thread::get_id();
        started = true;
        while (!stop) std::this_thread::yield();
        sawStop = true;
        returned = true;
      },
      [&] {
        // Wait until the worker has taken the background (a background not started by the end never runs).
        for (int i = 0; i < 5000 && !started; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        EXPECT_FALSE(sawStop.load());  // it runs as long as the foreground does
      });
  ASSERT_TRUE(started.load());
  EXPECT_TRUE(returned.load());  // joined before runAlongside returned
  EXPECT_TRUE(sawStop.load());
  EXPECT_NE(backgroundThread, caller);
  // The pool is free again: a loop after it runs on both threads.
  std::atomic<int> chunks{0};
  EXPECT_TRUE(detail::parallelFor(64, 1, [&](size_t, size_t, size_t) { ++chunks; }));
  EXPECT_EQ(chunks.load(), 64);
}

TEST(Threads, RunAlongsideOnOneThreadRunsOnlyTheForeground) {
  ThreadCountScope scope(1);
  bool foreground = false, background = false;
  detail::runAlongside([&](const std::atomic<bool>&) { background = true; }, [&] { foreground = true; });
  EXPECT_TRUE(foreground);
  EXPECT_FALSE(background);
}

TEST(Threads, RunAlongsidePropagatesForegroundExceptionsAfterTheBackgroundStopsAndDropsBackgroundOnes) {
  if (!kThreads) GTEST_SKIP() << "no threads in this build";
  ThreadCountScope scope(2);
  std::atomic<bool> started{false}, stopped{false};
  auto waitForStart = [&] {
    for (int i = 0; i < 5000 && !started; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  };
  EXPECT_THROW(detail::runAlongside(
                   [&](const std::atomic<bool>& stop) {
                     started = true;
                     while (!stop) std::this_thread::yield();
                     stopped = true;
                   },
                   [&] {
                     waitForStart();
                     throw std::runtime_error("load failed");
                   }),
               std::runtime_error);
  EXPECT_TRUE(stopped.load());
  started = false;
  bool foreground = false;
  EXPECT_NO_THROW(detail::runAlongside(
      [&](const std::atomic<bool>&) {
        started = true;
        throw std::runtime_error("warm-up failed");
      },
      [&] {
        waitForStart();
        foreground = true;
      }));
  EXPECT_TRUE(foreground);
}

/// The warm-up of a load (warm_up.hpp) runs beside it and changes nothing the mesh gives afterwards.
TEST(Threads, LoadWhileWarmingUpLoadsTheSameMeshAndTheNextParameterizationIsBitIdentical) {
  const TriMesh reference = makeHeightField(60);
  ParamOptions options;
  const auto before = parameterize(reference, options);
  ASSERT_TRUE(before);
  for (int threads : {1, 2}) {
    ThreadCountScope scope(threads);
    std::optional<TriMesh> mesh;
    loadWhileWarmingUp(WarmUp{std::size_t{64} << 20, {}, MeshFormat::Auto, true}, [&] { mesh = makeHeightField(60); });
    ASSERT_TRUE(mesh.has_value());
    EXPECT_TRUE(sameBits(mesh->positions(), reference.positions()));
    const auto after = parameterize(*mesh, options);
    ASSERT_TRUE(after);
    EXPECT_TRUE(sameBits(after.value().uv, before.value().uv)) << threads << " threads";
    // A file's warm-up (its vertices counted on the worker, while the same bytes are parsed).
    const std::string obj = writeObj(reference);
    std::optional<Expected<TriMesh>> loaded;
    loadWhileWarmingUp(WarmUp{0, obj, MeshFormat::Obj, true}, [&] { loaded = loadMesh(obj, MeshFormat::Obj); });
    ASSERT_TRUE(loaded.has_value() && *loaded);
    const auto plain = loadMesh(obj, MeshFormat::Obj);
    ASSERT_TRUE(plain);
    EXPECT_TRUE(sameBits(loaded->value().positions(), plain.value().positions()));
    EXPECT_TRUE(
        sameBits(parameterize(loaded->value(), options).value().uv, parameterize(plain.value(), options).value().uv));
  }
}

/// A load that fails returns its own error beside the warm-up, whatever the header claims (the count is
/// capped by the limit and by what the bytes can hold, so nothing near the claim is allocated).
TEST(Threads, ALoadThatFailsWhileWarmingUpReturnsItsError) {
  const std::string lying = "OFF\n2000000000 1 0\n0 0 0\n";
  BuildLimits limits;
  limits.maxVertices = 1000;
  for (int threads : {1, 2}) {
    ThreadCountScope scope(threads);
    std::optional<Expected<TriMesh>> loaded;
    loadWhileWarmingUp(WarmUp{0, lying, MeshFormat::Off, true, limits.maxVertices},
                       [&] { loaded = loadMesh(lying, MeshFormat::Off, limits); });
    ASSERT_TRUE(loaded.has_value());
    ASSERT_FALSE(*loaded);
    EXPECT_EQ(loaded->error().code, loadMesh(lying, MeshFormat::Off, limits).error().code) << threads << " threads";
  }
}

}  // namespace
}  // namespace straightest
