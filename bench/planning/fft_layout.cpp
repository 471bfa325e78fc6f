// Does the layout of the spectrum change the cost of a large 2D transform?
// Times one forward + backward pair of an n x n real array three ways, with
// raw FFTW (threads from FFTW's OpenMP build):
//   plain       FFTW's 2D r2c/c2r plans (the serial operators' transform);
//   transposed  rows r2c, then the columns c2c written transposed (one
//               strided guru plan each way), the spectrum kx-major as a
//               slab transform's (FFTW_MPI_TRANSPOSED_OUT);
//   blocked     rows r2c, a cache-blocked transpose, contiguous c2c rows
//               in place (and back the same way);
//   columns     rows r2c, then the columns in blocks of kBlock: each block
//               gathered into a small contiguous buffer, transformed there
//               and scattered back; FFTW's layout kept, no second spectrum;
//   fused       rows r2c kRows at a time into a small buffer, scattered
//               transposed into the spectrum, then its contiguous c2c rows
//               in place (backward: the reverse): transposed as blocked,
//               without its second spectrum or transpose passes.
// The columns of a 16384^2 array are 128 KiB apart: every element of a
// column pass on a different page (docs/development-log.md, issue 31).
// Each variant checks its round trip against n^2 times the input.
//
//   fft_layout N plain|transposed|blocked|columns THREADS [PAIRS] [estimate|measure]
//
// Prints: n variant threads planning plan_s pair_s max_round_trip_error.
#include <fftw3.h>
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

namespace {

using Clock = std::chrono::steady_clock;
using Complex = std::complex<double>;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// out (cols x rows) = in (rows x cols) transposed, in tiles that fit in L1.
void transpose(const Complex* in, Complex* out, std::size_t rows, std::size_t cols) {
  constexpr std::size_t kTile = 32;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t tr = 0; tr < static_cast<std::ptrdiff_t>((rows + kTile - 1) / kTile); ++tr) {
    const std::size_t r0 = static_cast<std::size_t>(tr) * kTile;
    const std::size_t r1 = std::min(rows, r0 + kTile);
    for (std::size_t c0 = 0; c0 < cols; c0 += kTile) {
      const std::size_t c1 = std::min(cols, c0 + kTile);
      for (std::size_t c = c0; c < c1; ++c) {
        for (std::size_t r = r0; r < r1; ++r) out[c * rows + r] = in[r * cols + c];
      }
    }
  }
}

class Pair {
 public:
  Pair(std::size_t n, const std::string& variant, unsigned flags) : n_(n), h_(n / 2 + 1), variant_(variant) {
    const int ni = static_cast<int>(n);
    const int hi = static_cast<int>(h_);
    x_ = fftw_alloc_real(n * n);
    y_ = fftw_alloc_real(n * n);
    s_ = fftw_alloc_complex(n * h_);
    auto* s = s_;
    if (variant == "plain") {
      plans_[0] = fftw_plan_dft_r2c_2d(ni, ni, x_, s, flags | FFTW_PRESERVE_INPUT);
      plans_[1] = fftw_plan_dft_c2r_2d(ni, ni, s, y_, flags | FFTW_DESTROY_INPUT);
    } else if (variant == "transposed" || variant == "blocked") {
      t_ = fftw_alloc_complex(n * h_);
      auto* t = t_;
      // rows: n transforms of n reals, contiguous
      plans_[0] = fftw_plan_many_dft_r2c(1, &ni, ni, x_, nullptr, 1, ni, s, nullptr, 1, hi, flags);
      plans_[3] = fftw_plan_many_dft_c2r(1, &ni, ni, s, nullptr, 1, hi, y_, nullptr, 1, ni, flags);
      if (variant == "transposed") {
        // columns: h transforms of n values h apart, written as rows of t
        plans_[1] = fftw_plan_many_dft(1, &ni, hi, s, nullptr, hi, 1, t, nullptr, 1, ni, FFTW_FORWARD, flags);
        plans_[2] = fftw_plan_many_dft(1, &ni, hi, t, nullptr, 1, ni, s, nullptr, hi, 1, FFTW_BACKWARD, flags);
      } else {
        plans_[1] = fftw_plan_many_dft(1, &ni, hi, t, nullptr, 1, ni, t, nullptr, 1, ni, FFTW_FORWARD, flags);
        plans_[2] = fftw_plan_many_dft(1, &ni, hi, t, nullptr, 1, ni, t, nullptr, 1, ni, FFTW_BACKWARD, flags);
      }
    } else if (variant == "columns") {
      plans_[0] = fftw_plan_many_dft_r2c(1, &ni, ni, x_, nullptr, 1, ni, s, nullptr, 1, hi, flags);
      plans_[3] = fftw_plan_many_dft_c2r(1, &ni, ni, s, nullptr, 1, hi, y_, nullptr, 1, ni, flags);
      threads_ = omp_get_max_threads();
      buffers_ = fftw_alloc_complex(static_cast<std::size_t>(threads_) * kBlock * n);
      fftw_plan_with_nthreads(1);
      plans_[1] =
          fftw_plan_many_dft(1, &ni, kBlock, buffers_, nullptr, 1, ni, buffers_, nullptr, 1, ni, FFTW_FORWARD, flags);
      plans_[2] =
          fftw_plan_many_dft(1, &ni, kBlock, buffers_, nullptr, 1, ni, buffers_, nullptr, 1, ni, FFTW_BACKWARD, flags);
      fftw_plan_with_nthreads(threads_);
    } else if (variant == "fused" || variant == "fused2") {
      // fused2: the rows' spectra written kx-major into the buffer (entry
      // c of row r at c * kRows + r), so that the scatter copies 16
      // consecutive entries per kx.
      const bool strided = variant == "fused2";
      threads_ = omp_get_max_threads();
      buffers_ = fftw_alloc_complex(static_cast<std::size_t>(threads_) * kRows * h_);
      const int rows = kRows;
      fftw_plan_with_nthreads(1);
      plans_[0] = fftw_plan_many_dft_r2c(1, &ni, rows, x_, nullptr, 1, ni, buffers_, nullptr, strided ? rows : 1,
                                         strided ? 1 : hi, flags);
      plans_[3] = fftw_plan_many_dft_c2r(1, &ni, rows, buffers_, nullptr, strided ? rows : 1, strided ? 1 : hi, y_,
                                         nullptr, 1, ni, flags);
      strided_ = strided;
      fftw_plan_with_nthreads(threads_);
      plans_[1] = fftw_plan_many_dft(1, &ni, hi, s, nullptr, 1, ni, s, nullptr, 1, ni, FFTW_FORWARD, flags);
      plans_[2] = fftw_plan_many_dft(1, &ni, hi, s, nullptr, 1, ni, s, nullptr, 1, ni, FFTW_BACKWARD, flags);
    } else {
      throw std::invalid_argument("variant " + variant +
                                  ": allowed are plain, transposed, blocked, columns, fused and fused2");
    }
    const int planned = variant == "plain" ? 2 : 4;
    for (int k = 0; k < planned; ++k) {
      if (plans_[k] == nullptr) throw std::runtime_error("FFTW could not plan the " + variant + " transforms");
    }
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (std::size_t i = 0; i < n * n; ++i) x_[i] = uniform(random);
  }
  ~Pair() {
    for (fftw_plan p : plans_) {
      if (p != nullptr) fftw_destroy_plan(p);
    }
    fftw_free(x_);
    fftw_free(y_);
    fftw_free(s_);
    if (t_ != nullptr) fftw_free(t_);
    if (buffers_ != nullptr) fftw_free(buffers_);
  }
  Pair(const Pair&) = delete;
  Pair& operator=(const Pair&) = delete;

  void run() {
    if (variant_ == "plain") {
      fftw_execute(plans_[0]);
      fftw_execute(plans_[1]);
    } else if (variant_ == "transposed") {
      for (fftw_plan p : plans_) fftw_execute(p);
    } else if (variant_ == "fused" || variant_ == "fused2") {
      rows_to_spectrum();
      fftw_execute(plans_[1]);
      fftw_execute(plans_[2]);
      spectrum_to_rows();
    } else if (variant_ == "columns") {
      fftw_execute(plans_[0]);
      column_pass(plans_[1]);
      column_pass(plans_[2]);
      fftw_execute(plans_[3]);
    } else {
      auto* s = reinterpret_cast<Complex*>(s_);
      auto* t = reinterpret_cast<Complex*>(t_);
      fftw_execute(plans_[0]);
      transpose(s, t, n_, h_);
      fftw_execute(plans_[1]);
      fftw_execute(plans_[2]);
      transpose(t, s, h_, n_);
      fftw_execute(plans_[3]);
    }
  }
  double round_trip_error() const {
    const double scale = 1.0 / static_cast<double>(n_ * n_);
    double worst = 0.0;
    for (std::size_t i = 0; i < n_ * n_; ++i) worst = std::max(worst, std::abs(y_[i] * scale - x_[i]));
    return worst;
  }

 private:
  static constexpr int kBlock = 16;
  static constexpr int kRows = 16;

  // fused, forward: kRows rows of x at a time through r2c into a thread's
  // buffer, then into the spectrum's columns (kx-major, n entries each).
  void rows_to_spectrum() {
    auto* s = reinterpret_cast<Complex*>(s_);
    const std::size_t blocks = n_ / kRows;  // n a multiple of kRows here
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t>(blocks); ++b) {
      auto* buffer = reinterpret_cast<Complex*>(buffers_) + static_cast<std::size_t>(omp_get_thread_num()) * kRows * h_;
      const std::size_t r0 = static_cast<std::size_t>(b) * kRows;
      fftw_execute_dft_r2c(plans_[0], x_ + r0 * n_, reinterpret_cast<fftw_complex*>(buffer));
      if (strided_) {
        for (std::size_t c = 0; c < h_; ++c) std::copy_n(buffer + c * kRows, kRows, s + c * n_ + r0);
      } else {
        for (std::size_t c = 0; c < h_; ++c) {
          Complex* column = s + c * n_ + r0;
          for (std::size_t r = 0; r < kRows; ++r) column[r] = buffer[r * h_ + c];
        }
      }
    }
  }
  // fused, backward: the reverse, into y.
  void spectrum_to_rows() {
    auto* s = reinterpret_cast<Complex*>(s_);
    const std::size_t blocks = n_ / kRows;
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t>(blocks); ++b) {
      auto* buffer = reinterpret_cast<Complex*>(buffers_) + static_cast<std::size_t>(omp_get_thread_num()) * kRows * h_;
      const std::size_t r0 = static_cast<std::size_t>(b) * kRows;
      if (strided_) {
        for (std::size_t c = 0; c < h_; ++c) std::copy_n(s + c * n_ + r0, kRows, buffer + c * kRows);
      } else {
        for (std::size_t c = 0; c < h_; ++c) {
          const Complex* column = s + c * n_ + r0;
          for (std::size_t r = 0; r < kRows; ++r) buffer[r * h_ + c] = column[r];
        }
      }
      fftw_execute_dft_c2r(plans_[3], reinterpret_cast<fftw_complex*>(buffer), y_ + r0 * n_);
    }
  }

  // Every column of s through `plan`, kBlock columns at a time.
  void column_pass(fftw_plan plan) {
    auto* s = reinterpret_cast<Complex*>(s_);
    const std::size_t blocks = (h_ + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static) num_threads(threads_)
    for (std::ptrdiff_t b = 0; b < static_cast<std::ptrdiff_t>(blocks); ++b) {
      auto* buffer =
          reinterpret_cast<Complex*>(buffers_) + static_cast<std::size_t>(omp_get_thread_num()) * kBlock * n_;
      const std::size_t c0 = static_cast<std::size_t>(b) * kBlock;
      const std::size_t width = std::min<std::size_t>(kBlock, h_ - c0);
      for (std::size_t r = 0; r < n_; ++r) {
        for (std::size_t c = 0; c < width; ++c) buffer[c * n_ + r] = s[r * h_ + c0 + c];
      }
      for (std::size_t c = width; c < kBlock; ++c) std::fill_n(buffer + c * n_, n_, Complex{});
      fftw_execute_dft(plan, reinterpret_cast<fftw_complex*>(buffer), reinterpret_cast<fftw_complex*>(buffer));
      for (std::size_t r = 0; r < n_; ++r) {
        for (std::size_t c = 0; c < width; ++c) s[r * h_ + c0 + c] = buffer[c * n_ + r];
      }
    }
  }

  std::size_t n_;
  std::size_t h_;
  std::string variant_;
  double* x_ = nullptr;
  double* y_ = nullptr;
  fftw_complex* s_ = nullptr;
  fftw_complex* t_ = nullptr;
  fftw_complex* buffers_ = nullptr;  // columns: kBlock columns per thread
  int threads_ = 1;
  bool strided_ = false;  // fused2
  fftw_plan plans_[4] = {nullptr, nullptr, nullptr, nullptr};
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s N plain|transposed|blocked|columns THREADS [PAIRS] [estimate|measure]\n", argv[0]);
    return 2;
  }
  try {
    const std::size_t n = std::stoul(argv[1]);
    const std::string variant = argv[2];
    const int threads = std::stoi(argv[3]);
    const int pairs = argc > 4 ? std::stoi(argv[4]) : 5;
    const std::string planning = argc > 5 ? argv[5] : "measure";
    if (planning != "estimate" && planning != "measure") {
      throw std::invalid_argument("planning " + planning + ": allowed are estimate and measure");
    }
    fftw_init_threads();
    fftw_plan_with_nthreads(threads);
    omp_set_num_threads(threads);
    const auto start = Clock::now();
    Pair pair(n, variant, planning == "measure" ? FFTW_MEASURE : FFTW_ESTIMATE);
    const double plan = seconds_since(start);
    pair.run();  // warm-up, and the round trip checked
    const double error = pair.round_trip_error();
    const auto timed = Clock::now();
    for (int k = 0; k < pairs; ++k) pair.run();
    fmt::print("{} {} {} {} {:.2f} {:.5f} {:.1e}\n", n, variant, threads, planning, plan, seconds_since(timed) / pairs,
               error);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
