// Private: the blocks of rows a transposed transform (RealFft with
// FftLayout::transposed, PaddedRealFft in 2D) takes through its per-thread
// buffers on the way to and from its kx blocks.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>

namespace halfspace::fft::detail {

// Rows per block: a multiple of 16, so that every block of a real array
// starts at its first row's alignment (16 rows of floats are a multiple of
// 64 bytes) and one FFTW plan serves every full block. 64 rather than 16:
// each kx block then receives 1 kB runs, not 256 B, and whole products ran
// 5-10 % faster from 512^2 to 4096^2 (development log, 2026-12-01).
inline constexpr std::size_t kBlockRows = 64;

// body(thread, first, count) for the blocks of kBlockRows of `rows` rows
// (count fewer in the last), in parallel on at most `buffers` threads;
// `thread` numbers the caller's buffer the block may use.
template <class Body>
void for_each_row_block(std::size_t rows, int buffers, Body&& body) {
  const auto blocks = static_cast<std::ptrdiff_t>((rows + kBlockRows - 1) / kBlockRows);
  const int team = static_cast<int>(std::min<std::ptrdiff_t>(buffers, blocks));
#pragma omp parallel for schedule(static) num_threads(team)
  for (std::ptrdiff_t b = 0; b < blocks; ++b) {
    const std::size_t first = static_cast<std::size_t>(b) * kBlockRows;
    body(omp_get_thread_num(), first, std::min(kBlockRows, rows - first));
  }
}

}  // namespace halfspace::fft::detail
