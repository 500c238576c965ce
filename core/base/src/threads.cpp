// threads.cpp — the process-wide thread count and parallelFor on a persistent thread pool (threads.hpp,
// parallel_for.hpp).
//
// The pool starts lazily, on the first parallelFor that may use more than one thread, with
// threadCount() − 1 workers (the caller is the last thread), and is rebuilt when the count changes.
// Chunks are handed out by one atomic counter, so a thread that finishes early takes the next chunk:
// which thread runs a chunk varies from run to run, but every chunk writes only its own data, so the
// results do not. threadCount() == 1 keeps the serial loop and never starts a thread.
//
// Waking a thread that sleeps on a condition variable is slow on a virtual machine: a worker joined
// every loop that late, and the caller, done first, slept until the last chunk's worker woke it. The
// solver runs hundreds of loops of a millisecond or less per solve, so both sides first spin for a
// while (kSpin) on an atomic before they sleep.
//
// A WebAssembly build without pthreads cannot create a thread (std::thread aborts there): it reports
// one hardware thread and always takes the serial loop.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "straightest/base/parallel_for.hpp"
#include "straightest/base/threads.hpp"

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
#define STRAIGHTEST_HAS_THREADS 0
#else
#define STRAIGHTEST_HAS_THREADS 1
#endif

namespace straightest {

namespace {
constexpr int kMaxThreads = 64;
std::atomic<int> requestedThreads{0};  // every hardware thread unless set
}  // namespace

int hardwareThreads() {
#if STRAIGHTEST_HAS_THREADS
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#else
  return 1;
#endif
}

void setThreadCount(int count) { requestedThreads = std::clamp(count, 0, kMaxThreads); }

int threadCount() {
#if STRAIGHTEST_HAS_THREADS
  const int requested = requestedThreads.load();
  return requested == 0 ? std::min(hardwareThreads(), kMaxThreads) : requested;
#else
  return 1;
#endif
}

namespace detail {

namespace {

using Body = std::function<void(std::size_t chunk, std::size_t begin, std::size_t end)>;

/// How long a thread polls before it sleeps: longer than a wake-up, shorter than anything a user sees.
constexpr std::chrono::microseconds kSpin{50};

/// Polls ready() until it holds or kSpin has passed; whether it held.
template <class Ready>
bool spinUntil(const Ready& ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  do {
    for (int k = 0; k < 64; ++k)
      if (ready()) return true;
  } while (std::chrono::steady_clock::now() < until);
  return ready();
}

/// The chunks [0, chunks) of [0, count) through `body`: runChunks takes one at a time from `next`.
struct Job {
  std::size_t count = 0, grain = 0, chunks = 0;
  const Body* body = nullptr;
  std::atomic<std::size_t> next{0};      // the next chunk to hand out
  std::atomic<std::size_t> finished{0};  // chunks done (for progress)
  std::atomic<bool> stop{false};         // cancelled, or a body threw: hand out no new chunk
  std::mutex errorMutex;
  std::exception_ptr error;           // the first exception a body threw, rethrown on the calling thread
  std::atomic<int> workersInside{0};  // workers running chunks of this job (changed under the pool's mutex)

  /// Runs one chunk if one is left; false when none is.
  bool runOne() {
    if (stop.load(std::memory_order_relaxed)) return false;
    const std::size_t chunk = next.fetch_add(1, std::memory_order_relaxed);
    if (chunk >= chunks) return false;
    try {
      (*body)(chunk, chunk * grain, std::min(count, (chunk + 1) * grain));
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      stop = true;
    }
    finished.fetch_add(1, std::memory_order_release);
    return true;
  }
};

#if STRAIGHTEST_HAS_THREADS
/// Worker threads that wait for a Job and help run its chunks. One parallelFor at a time uses the pool
/// (`busy`); another one meanwhile (from a second user thread, or from inside a chunk) runs serially.
class ThreadPool {
 public:
  ~ThreadPool() { resize(0); }

  std::mutex busy;  // held by the parallelFor using the pool

  /// Makes `workers` workers wait for jobs (the caller holds `busy`).
  void resize(int workers) {
    if (static_cast<int>(threads_.size()) == workers) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
      quitting_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
    threads_.clear();
    quit_ = false;
    quitting_ = false;
    for (int i = 0; i < workers; ++i) threads_.emplace_back([this] { workerLoop(); });
  }

  /// Offers `job` to the workers (the caller holds `busy` and runs chunks itself meanwhile).
  void start(Job& job) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      ++generation_;
      published_.store(generation_, std::memory_order_release);
    }
    wake_.notify_all();
  }

  /// Waits until no worker runs a chunk of `job` and withdraws it; calls `whileWaiting` every few
  /// milliseconds meanwhile (the caller's progress).
  template <class F>
  void finish(Job& job, F&& whileWaiting) {
    spinUntil([&] { return job.workersInside.load(std::memory_order_acquire) == 0; });
    std::unique_lock<std::mutex> lock(mutex_);
    while (job.workersInside > 0) {
      if (done_.wait_for(lock, std::chrono::milliseconds(5)) == std::cv_status::timeout) {
        lock.unlock();
        whileWaiting();
        lock.lock();
      }
    }
    job_ = nullptr;  // a worker that wakes up late finds nothing to do
  }

 private:
  void workerLoop() {
    insideLoop() = true;
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      if (!quit_ && generation_ == seen) {  // no job yet: poll a while before sleeping
        lock.unlock();
        spinUntil([&] { return published_.load(std::memory_order_acquire) != seen || quitting_.load(); });
        lock.lock();
      }
      wake_.wait(lock, [&] { return quit_ || generation_ != seen; });
      if (quit_) return;
      seen = generation_;
      Job* job = job_;
      if (job == nullptr) continue;
      ++job->workersInside;
      lock.unlock();
      while (job->runOne()) {
      }
      lock.lock();
      if (--job->workersInside == 0) done_.notify_all();
    }
  }

 public:
  /// True on the pool's own threads, and on a calling thread while its loop runs: a parallelFor inside
  /// a chunk runs serially (the pool is taken, and the caller already holds `busy`).
  static bool& insideLoop() {
    thread_local bool flag = false;
    return flag;
  }

 private:
  std::vector<std::thread> threads_;
  std::mutex mutex_;  // guards job_, generation_, quit_ and every job's workersInside
  std::condition_variable wake_, done_;
  Job* job_ = nullptr;
  std::uint64_t generation_ = 0;
  std::atomic<std::uint64_t> published_{0};  // generation_, for polling without the mutex
  bool quit_ = false;
  std::atomic<bool> quitting_{false};  // quit_, for polling
};

ThreadPool& pool() {
  static ThreadPool instance;
  return instance;
}
#endif

/// The single-threaded path: every chunk in order on the calling thread.
bool serialFor(std::size_t count, std::size_t grain, const Body& body, const Progress& progress, const char* stage) {
  const std::size_t chunks = chunkCount(count, grain);
  ThrottledProgress report(progress, stage);
  for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
    if (!report(static_cast<double>(chunk) / static_cast<double>(chunks))) return false;
    body(chunk, chunk * grain, std::min(count, (chunk + 1) * grain));
  }
  return chunks == 0 || report(1.0);
}

}  // namespace

bool parallelFor(std::size_t count, std::size_t grain, const Body& body, const Progress& progress, const char* stage) {
  const std::size_t chunks = chunkCount(count, grain);
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threadCount()), chunks));
#if STRAIGHTEST_HAS_THREADS
  if (threads <= 1 || ThreadPool::insideLoop()) return serialFor(count, grain, body, progress, stage);
  ThreadPool& workers = pool();
  std::unique_lock<std::mutex> busy(workers.busy, std::try_to_lock);
  if (!busy.owns_lock()) return serialFor(count, grain, body, progress, stage);
  // Sized by the thread count, not by this loop's chunks, so a short loop does not shrink the pool.
  workers.resize(threadCount() - 1);
  Job job;
  job.count = count;
  job.grain = grain;
  job.chunks = chunks;
  job.body = &body;
  ThrottledProgress report(progress, stage);
  auto done = [&] { return static_cast<double>(job.finished.load(std::memory_order_acquire)) / chunks; };
  bool cancelled = false;
  auto reportDone = [&] {
    if (!cancelled && !report(done())) {
      cancelled = true;
      job.stop = true;
    }
  };
  if (!report(0.0)) return false;  // the stage's start, before any chunk runs
  workers.start(job);
  try {
    ThreadPool::insideLoop() = true;
    while (job.runOne()) reportDone();
    ThreadPool::insideLoop() = false;
    workers.finish(job, reportDone);
  } catch (...) {  // the progress callback threw: no worker may outlive the job on this stack
    job.stop = true;
    ThreadPool::insideLoop() = false;
    workers.finish(job, [] {});
    throw;
  }
  if (job.error) std::rethrow_exception(job.error);
  if (cancelled) return false;
  return report(1.0);
#else
  (void)threads;
  return serialFor(count, grain, body, progress, stage);
#endif
}

void runAlongside(const std::function<void(const std::atomic<bool>& stop)>& background,
                  const std::function<void()>& foreground) {
#if STRAIGHTEST_HAS_THREADS
  if (threadCount() < 2 || ThreadPool::insideLoop()) return foreground();
  ThreadPool& workers = pool();
  std::unique_lock<std::mutex> busy(workers.busy, std::try_to_lock);
  if (!busy.owns_lock()) return foreground();
  try {
    workers.resize(threadCount() - 1);
  } catch (...) {  // no worker could be started (std::system_error): the aid is dropped, the work runs alone
    busy.unlock();
    return foreground();
  }
  std::atomic<bool> stop{false};
  const Body body = [&](std::size_t, std::size_t, std::size_t) {
    try {
      background(stop);
    } catch (...) {  // an aid only: its failure must not fail the caller's work
    }
  };
  Job job;  // one chunk, which only a worker takes: the caller never calls runOne
  job.count = job.grain = job.chunks = 1;
  job.body = &body;
  workers.start(job);
  auto join = [&] {
    stop = true;
    job.stop = true;  // not taken yet: nobody will
    ThreadPool::insideLoop() = false;
    workers.finish(job, [] {});
  };
  ThreadPool::insideLoop() = true;  // foreground's own loops run serially: the pool is taken
  try {
    foreground();
  } catch (...) {
    join();
    throw;
  }
  join();
#else
  (void)background;
  foreground();
#endif
}

}  // namespace detail
}  // namespace straightest
