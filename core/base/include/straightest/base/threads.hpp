// threads.hpp — how many threads the core's data-parallel loops use.
// Process-wide, like Eigen::setNbThreads: a CLI run, a WASM module instance or a test sets it once;
// every later call uses it. The loops it governs (traces to many targets, interior weights, stretch
// metrics, the solver's sparse products) split their work into chunks whose boundaries depend only
// on the problem size, never on the thread count, so results are bit-identical for any count.
// Progress callbacks and cancellation checks run on the calling thread only (in WebAssembly a
// JavaScript callback may only run on the thread that owns it).
#pragma once

namespace straightest {

/// Sets the number of threads for later calls: 0 = every hardware thread (hardwareThreads()),
/// 1 = the single-threaded code path (no thread is ever started); larger values are capped at 64.
/// Negative values are treated as 0, which is also the default.
void setThreadCount(int count);

/// The thread count in effect (>= 1).
int threadCount();

/// The hardware threads available (std::thread::hardware_concurrency(), at least 1; 1 in a
/// WebAssembly build without pthreads).
int hardwareThreads();

}  // namespace straightest
