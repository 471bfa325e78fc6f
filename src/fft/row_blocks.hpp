// Private: the blocks of rows a transposed transform (RealFft with
// FftLayout::transposed, PaddedRealFft in 2D) takes through its per-thread
// buffers on the way to and from its kx blocks.
#pragma once

#include <omp.h>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace halfspace::fft::detail {

// Rows per block: a multiple of 16, so that every block of a real array
// starts at its first row's alignment (16 rows of floats are a multiple of
// 64 bytes) and one FFTW plan serves every full block. 64 rather than 16:
// each kx block then receives 1 kB runs, not 256 B, and whole solves ran
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

// Spectra larger than this are written by streaming stores (store_entry):
// 2048^2 and 4096^2 solves ran 3-5 % faster so, 1024^2 (8 MiB) and 512^2
// ones 8-20 % slower, their spectra read back from the caches otherwise
// (development log, 2026-12-01).
inline constexpr std::size_t kStreamingSpectrumBytes = std::size_t{16} << 20;

// Stores `value` at `to`; streaming (the line written without being read
// first, and not kept in the caches) for spectra past the caches.
template <class Real>
inline void store_entry(std::complex<Real>* to, const std::complex<Real>& value, bool streaming) {
#if defined(__SSE2__) && defined(__x86_64__)
  if (streaming) {
    if constexpr (std::is_same_v<Real, double>) {
      _mm_stream_pd(reinterpret_cast<double*>(to), _mm_loadu_pd(reinterpret_cast<const double*>(&value)));
    } else {
      long long bits = 0;  // a float entry's 8 bytes
      std::memcpy(&bits, &value, sizeof bits);
      _mm_stream_si64(reinterpret_cast<long long*>(to), bits);
    }
    return;
  }
#endif
  (void)streaming;
  *to = value;
}

// A block of `count` row spectra (`cols` entries each, row r at
// rows[r * cols]) into the kx columns (column c at columns[c * length],
// entries first .. first + count - 1).
template <class Real>
void scatter_block(const std::complex<Real>* rows, std::size_t cols, std::complex<Real>* columns, std::size_t length,
                   std::size_t first, std::size_t count, bool streaming) {
  for (std::size_t c = 0; c < cols; ++c) {
    std::complex<Real>* const to = columns + c * length + first;
    for (std::size_t r = 0; r < count; ++r) store_entry(to + r, rows[r * cols + c], streaming);
  }
#if defined(__SSE2__)
  if (streaming) _mm_sfence();
#endif
}

// The inverse of scatter_block: the kx columns' entries first .. first +
// count - 1 back into a block of row spectra.
template <class Real>
void gather_block(const std::complex<Real>* columns, std::size_t length, std::complex<Real>* rows, std::size_t cols,
                  std::size_t first, std::size_t count) {
  for (std::size_t c = 0; c < cols; ++c) {
    const std::complex<Real>* const from = columns + c * length + first;
    for (std::size_t r = 0; r < count; ++r) rows[r * cols + c] = from[r];
  }
}

}  // namespace halfspace::fft::detail
