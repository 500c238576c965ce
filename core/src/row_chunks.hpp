// row_chunks.hpp — the solver's data-parallel loops over rows: fixed chunks of kRowGrain rows run by
// parallelFor (parallel_for.hpp), and sums over rows kept per chunk and added in chunk order, so every
// result is bit-identical for any thread count (the chunks depend only on the row count). Internal to
// the solver sources.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "parallel_for.hpp"

namespace straightest::detail {

/// Rows per chunk: large enough that a chunk's work (a few hundred microseconds of a sparse product
/// at the finest level) dwarfs handing it to a thread, small enough for ~100 chunks at 1M rows.
inline constexpr std::size_t kRowGrain = 8192;

/// body(begin, end) for every chunk of [0, rows); chunks may run at the same time.
template <class Body>
void forRowChunks(std::size_t rows, const Body& body) {
  parallelFor(rows, kRowGrain, [&body](std::size_t, std::size_t begin, std::size_t end) { body(begin, end); });
}

/// N sums over [0, rows): body(begin, end, sums) adds its chunk's rows into sums (N doubles, zero on
/// entry); the chunks' sums are then added in chunk order, whatever thread ran them.
template <std::size_t N, class Body>
std::array<double, N> sumRowChunks(std::size_t rows, const Body& body) {
  std::vector<std::array<double, N>> partial(chunkCount(rows, kRowGrain));
  parallelFor(rows, kRowGrain, [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    std::array<double, N> sums{};
    body(begin, end, sums.data());
    partial[chunk] = sums;
  });
  std::array<double, N> total{};
  for (const std::array<double, N>& sums : partial)
    for (std::size_t k = 0; k < N; ++k) total[k] += sums[k];
  return total;
}

}  // namespace straightest::detail
