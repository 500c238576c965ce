// row_chunks.hpp — the solver's data-parallel loops over rows: fixed chunks of kRowGrain rows run by
// parallelFor (parallel_for.hpp), and sums over rows kept per chunk and added in chunk order, so every
// result is bit-identical for any thread count (the chunks depend only on the row count). Internal to
// the solver sources.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "straightest/base/parallel_for.hpp"

namespace straightest::detail {

/// Rows per chunk: large enough that a chunk's work (a few hundred microseconds of a sparse product
/// at the finest level) dwarfs handing it to a thread, small enough for ~100 chunks at 1M rows.
inline constexpr std::size_t kRowGrain = 8192;

/// Coarser units than the chunks, for work that needs state of its own per unit (a sparse accumulator
/// with a slot per column, a block of Gauss–Seidel rows): [0, rows) cut into at most kRowPieces pieces
/// of at least kRowPieceMinRows rows (one piece below that), fixed by the row count alone. Returns every
/// piece's first row, then rows.
inline constexpr std::int32_t kRowPieces = 16, kRowPieceMinRows = 16384;
inline std::vector<std::int32_t> rowPieces(std::int32_t rows) {
  const std::int32_t pieces = std::clamp(rows / kRowPieceMinRows, std::int32_t{1}, kRowPieces);
  std::vector<std::int32_t> first(static_cast<std::size_t>(pieces) + 1);
  for (std::int32_t p = 0; p <= pieces; ++p)
    first[p] = static_cast<std::int32_t>(static_cast<std::int64_t>(rows) * p / pieces);
  return first;
}

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
