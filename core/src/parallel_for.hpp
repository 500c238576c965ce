// parallel_for.hpp — the one way the core runs a loop on several threads (threads.hpp).
// [0, count) is cut into chunks of `grain` elements (the last may be shorter); the chunking depends
// only on count and grain, so a reduction that keeps one partial result per chunk and combines them
// in chunk order gives bit-identical results for any thread count.
#pragma once
#include <cstddef>
#include <functional>

#include "straightest/progress.hpp"

namespace straightest::detail {

/// The number of chunks parallelFor cuts [0, count) into.
inline std::size_t chunkCount(std::size_t count, std::size_t grain) {
  return grain == 0 ? 0 : (count + grain - 1) / grain;
}

/// Calls body(chunk, begin, end) once for every chunk of [0, count) (grain > 0), on up to
/// threadCount() threads; the calling thread takes part. Bodies of different chunks may run at the
/// same time: they must write disjoint data. Only the calling thread calls `progress` (with `stage`
/// and the fraction of chunks done); when it returns false no new chunk starts, the running ones
/// finish, and parallelFor returns false. Returns true when every chunk ran.
bool parallelFor(std::size_t count, std::size_t grain,
                 const std::function<void(std::size_t chunk, std::size_t begin, std::size_t end)>& body,
                 const Progress& progress = {}, const char* stage = "");

}  // namespace straightest::detail
