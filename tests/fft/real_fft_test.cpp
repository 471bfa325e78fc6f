// The RAII real FFT plan pair against a direct DFT, its normalisation, the
// input-preserving forward transform the DC-FFT padding relies on, and moves.
#include "halfspace/fft/real_fft.hpp"

#include <fftw3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/threads.hpp"

namespace halfspace {
namespace {

// FFT against an O(N^2) DFT of O(1) data: rounding grows like eps log N.
constexpr double kTransformTolerance = 1e-13;

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> values(n);
  for (double& v : values) v = uniform(engine);
  return values;
}

// sum_{r, c} x(r, c) exp(-2 pi i (kr r / rows + kc c / cols)).
std::complex<double> direct_dft(const std::vector<double>& x, std::size_t rows, std::size_t cols, std::size_t kr,
                                std::size_t kc) {
  std::complex<double> sum = 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      const double phase = 2.0 * std::numbers::pi *
                           (static_cast<double>((kr * r) % rows) / static_cast<double>(rows) +
                            static_cast<double>((kc * c) % cols) / static_cast<double>(cols));
      sum += x[r * cols + c] * std::polar(1.0, -phase);
    }
  }
  return sum;
}

void expect_forward_matches_dft(RealFft& fft, unsigned seed) {
  const std::vector<double> x = random_values(fft.real_size(), seed);
  std::copy(x.begin(), x.end(), fft.input().begin());
  fft.forward();
  double worst = 0.0;
  for (std::size_t kr = 0; kr < fft.rows(); ++kr) {
    for (std::size_t kc = 0; kc < fft.spectrum_cols(); ++kc) {
      const auto expected = direct_dft(x, fft.rows(), fft.cols(), kr, kc);
      const std::size_t k = fft.transposed() ? kc * fft.rows() + kr : kr * fft.spectrum_cols() + kc;
      worst = std::max(worst, std::abs(fft.spectrum()[k] - expected));
    }
  }
  EXPECT_LE(worst, kTransformTolerance * static_cast<double>(fft.real_size()))
      << fft.rows() << "x" << fft.cols() << ": largest error " << worst;
  // r2c leaves its input alone.
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(fft.input()[i], x[i]) << "input changed at " << i;
}

TEST(RealFftTest, ForwardMatchesDirectDft1D) {
  for (const std::size_t n : {1u, 7u, 8u, 30u}) {
    RealFft fft(n, FftPlanning::estimate);
    EXPECT_EQ(fft.spectrum_size(), n / 2 + 1);
    expect_forward_matches_dft(fft, static_cast<unsigned>(n));
  }
}

TEST(RealFftTest, ForwardMatchesDirectDft2D) {
  RealFft odd(5, 7, FftPlanning::estimate);
  EXPECT_EQ(odd.spectrum_size(), 5u * 4u);
  expect_forward_matches_dft(odd, 1);
  RealFft even(6, 8, FftPlanning::estimate);
  expect_forward_matches_dft(even, 2);
}

TEST(RealFftTest, BackwardOfForwardIsSizeTimesInput) {
  RealFft fft(6, 10, FftPlanning::estimate);
  const std::vector<double> x = random_values(fft.real_size(), 3);
  std::copy(x.begin(), x.end(), fft.input().begin());
  fft.forward();
  fft.backward();
  const double n = static_cast<double>(fft.real_size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(fft.output()[i] / n, x[i], kTransformTolerance) << "at " << i;
  }
}

TEST(RealFftTest, BackwardCanOverwriteTheInput) {
  RealFft fft(7, 9, FftPlanning::estimate, FftOutput::overwrite_input);
  EXPECT_EQ(fft.output().data(), fft.input().data());
  const std::vector<double> x = random_values(fft.real_size(), 5);
  std::copy(x.begin(), x.end(), fft.input().begin());
  fft.forward();
  fft.backward();
  const double n = static_cast<double>(fft.real_size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(fft.input()[i] / n, x[i], kTransformTolerance) << "at " << i;
  }
}

// Over memory it does not own: the spectrum, then the real array, inside the
// workspace; the same bits as owned buffers; a workspace too small is refused.
TEST(RealFftTest, WorksInAGivenWorkspace) {
  for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{1, 10}, {1, 9}, {6, 10}, {5, 7}}) {
    const std::size_t size = RealFft::workspace_size(rows, cols);
    std::complex<double>* memory = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(size));
    ASSERT_NE(memory, nullptr);
    {
      RealFft owned = rows == 1 ? RealFft(cols, FftPlanning::estimate, FftOutput::overwrite_input)
                                : RealFft(rows, cols, FftPlanning::estimate, FftOutput::overwrite_input);
      RealFft given(rows, cols, FftPlanning::estimate, {memory, size});
      EXPECT_EQ(given.spectrum().data(), memory);
      EXPECT_GE(reinterpret_cast<const char*>(given.input().data()),
                reinterpret_cast<const char*>(memory + given.spectrum_size()));
      EXPECT_LE(reinterpret_cast<const char*>(given.input().data() + given.real_size()),
                reinterpret_cast<const char*>(memory + size));
      const std::vector<double> x = random_values(rows * cols, 17);
      std::copy(x.begin(), x.end(), owned.input().begin());
      std::copy(x.begin(), x.end(), given.input().begin());
      owned.forward();
      given.forward();
      for (std::size_t k = 0; k < owned.spectrum_size(); ++k) ASSERT_EQ(given.spectrum()[k], owned.spectrum()[k]);
      owned.backward();
      given.backward();
      for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(given.output()[i], owned.output()[i]);
    }  // the transform is gone; the workspace is still the caller's
    fftw_free(memory);
  }
  std::vector<std::complex<double>> small(RealFft::workspace_size(4, 6) - 1);
  EXPECT_THROW(RealFft(4, 6, FftPlanning::estimate, std::span<std::complex<double>>(small)), InputError);
}

// The caller's arrays give the same bits as the owned buffers, and an array
// FFTW cannot use (misaligned, wrong length) is refused without being touched.
TEST(RealFftTest, TransformsTheCallersArrays) {
  for (const FftOutput output : {FftOutput::separate, FftOutput::overwrite_input}) {
    RealFft fft(6, 10, FftPlanning::estimate, output);
    const std::vector<double> x = random_values(fft.real_size(), 9);
    std::copy(x.begin(), x.end(), fft.input().begin());
    fft.forward();
    const std::vector<std::complex<double>> owned_spectrum(fft.spectrum().begin(), fft.spectrum().end());
    fft.backward();
    const std::vector<double> owned_output(fft.output().begin(), fft.output().end());

    ASSERT_TRUE(fft.forward_from(x));
    for (std::size_t k = 0; k < owned_spectrum.size(); ++k) ASSERT_EQ(fft.spectrum()[k], owned_spectrum[k]) << k;
    std::vector<double> result(fft.real_size(), 0.0);
    ASSERT_TRUE(fft.backward_into(result));
    for (std::size_t i = 0; i < result.size(); ++i) ASSERT_EQ(result[i], owned_output[i]) << i;

    // One double past an aligned start is misaligned for FFTW's SIMD codelets.
    std::vector<double> shifted(fft.real_size() + 1, 7.0);
    EXPECT_FALSE(fft.backward_into(std::span<double>(shifted).subspan(1)));
    EXPECT_FALSE(fft.forward_from(std::span<const double>(shifted).subspan(1)));
    EXPECT_FALSE(fft.backward_into(std::span<double>(shifted).first(fft.real_size() - 1)));
    for (const double v : shifted) ASSERT_EQ(v, 7.0);
  }
}

TEST(RealFftTest, BuffersStartZeroAfterMeasuring) {
  // FFTW_MEASURE runs trial transforms in the buffers; they are cleared after.
  // One thread: measuring threaded plans is slow on a loaded machine.
  const int original = threads();
  set_threads(1);
  RealFft fft(16, 12, FftPlanning::measure);
  set_threads(original);
  for (const double v : fft.input()) ASSERT_EQ(v, 0.0);
  for (const double v : fft.output()) ASSERT_EQ(v, 0.0);
  for (const std::complex<double> z : fft.spectrum()) ASSERT_EQ(z, std::complex<double>(0.0, 0.0));
}

TEST(RealFftTest, IsMoveable) {
  RealFft a(12, FftPlanning::estimate);
  const double* buffer = a.input().data();
  RealFft b(std::move(a));
  EXPECT_EQ(b.input().data(), buffer);
  EXPECT_EQ(b.real_size(), 12u);
  RealFft c(4, FftPlanning::estimate);
  c = std::move(b);
  EXPECT_EQ(c.input().data(), buffer);
  expect_forward_matches_dft(c, 4);
}

// The single-precision transform (mixed precision's inner products) against
// the double one: the same spectrum to float rounding, which grows like
// eps_float log N (eps_float = 6e-8), and the same round trip.
TEST(RealFftTest, SinglePrecisionMatchesDoubleToFloatRounding) {
  constexpr std::size_t rows = 24;
  constexpr std::size_t cols = 20;
  const std::vector<double> x = random_values(rows * cols, 17);
  RealFft exact(rows, cols, FftPlanning::estimate);
  SingleRealFft single(rows, cols, FftPlanning::estimate);
  for (std::size_t i = 0; i < x.size(); ++i) {
    exact.input()[i] = x[i];
    single.input()[i] = static_cast<float>(x[i]);
  }
  exact.forward();
  single.forward();
  double largest = 0.0;
  double error = 0.0;
  for (std::size_t k = 0; k < exact.spectrum_size(); ++k) {
    const std::complex<double> z(single.spectrum()[k].real(), single.spectrum()[k].imag());
    largest = std::max(largest, std::abs(exact.spectrum()[k]));
    error = std::max(error, std::abs(z - exact.spectrum()[k]));
  }
  EXPECT_LT(error, 1e-6 * largest);
  EXPECT_GT(error, 1e-12 * largest) << "not single precision";
  single.backward();
  const double n = static_cast<double>(rows * cols);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(single.output()[i] / n, x[i], 1e-6) << i;
  EXPECT_THROW(SingleRealFft(0, FftPlanning::estimate), InputError);
}

// The transposed layout (kx-major: rows taken kBlockRows = 16 at a time
// through per-thread buffers) against the direct DFT, on shapes with
// and without a part block of rows, odd and even, on one and two threads;
// its round trip on its own and on the caller's arrays, in both precisions
// and in a workspace.
TEST(RealFftTest, TransposedLayoutMatchesDirectDftAndRoundTrips) {
  const int threads_before = threads();
  for (const int team : {1, 2}) {
    set_threads(team);
    for (const auto& [rows, cols] : std::vector<std::pair<std::size_t, std::size_t>>{
             {2, 3}, {5, 7}, {6, 8}, {16, 4}, {17, 9}, {33, 12}, {40, 1}}) {
      RealFft fft(rows, cols, FftPlanning::estimate, FftOutput::separate, FftLayout::transposed);
      ASSERT_TRUE(fft.transposed());
      EXPECT_EQ(fft.spectrum_blocks(), cols / 2 + 1);
      EXPECT_EQ(fft.spectrum_length(), rows);
      expect_forward_matches_dft(fft, static_cast<unsigned>(rows * 100 + cols));
      fft.backward();
      const double n = static_cast<double>(rows * cols);
      for (std::size_t i = 0; i < fft.real_size(); ++i) {
        ASSERT_NEAR(fft.output()[i] / n, fft.input()[i], 1e-14) << rows << "x" << cols << " at " << i;
      }
      // The caller's arrays (FFTW-aligned, as the solvers' are).
      RealFft own(rows, cols, FftPlanning::estimate, FftOutput::overwrite_input, FftLayout::transposed);
      double* values = fftw_alloc_real(rows * cols);
      const std::vector<double> x = random_values(rows * cols, 5);
      std::copy(x.begin(), x.end(), values);
      ASSERT_TRUE(own.forward_from({values, rows * cols}));
      std::copy(x.begin(), x.end(), fft.input().begin());
      fft.forward();
      for (std::size_t k = 0; k < own.spectrum_size(); ++k) {
        ASSERT_LE(std::abs(own.spectrum()[k] - fft.spectrum()[k]), 1e-12 * n) << k;
      }
      ASSERT_TRUE(own.backward_into({values, rows * cols}));
      for (std::size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(values[i] / n, x[i], 1e-14) << i;
      fftw_free(values);
    }
  }
  // A single row is row-major whatever is asked.
  EXPECT_FALSE(RealFft(1, 8, FftPlanning::estimate, FftOutput::separate, FftLayout::transposed).transposed());
  // Single precision and a workspace: the same layout, to float rounding.
  constexpr std::size_t rows = 19;
  constexpr std::size_t cols = 10;
  std::vector<std::complex<float>> memory(SingleRealFft::workspace_size(rows, cols) + 8);
  auto* aligned = reinterpret_cast<std::complex<float>*>(fftwf_alloc_complex(memory.size()));
  SingleRealFft single(rows, cols, FftPlanning::estimate, {aligned, memory.size()}, FftLayout::transposed);
  RealFft exact(rows, cols, FftPlanning::estimate, FftOutput::separate, FftLayout::transposed);
  const std::vector<double> x = random_values(rows * cols, 23);
  for (std::size_t i = 0; i < x.size(); ++i) {
    exact.input()[i] = x[i];
    single.input()[i] = static_cast<float>(x[i]);
  }
  exact.forward();
  single.forward();
  double error = 0.0;
  for (std::size_t k = 0; k < exact.spectrum_size(); ++k) {
    const std::complex<double> z(single.spectrum()[k].real(), single.spectrum()[k].imag());
    error = std::max(error, std::abs(z - exact.spectrum()[k]));
  }
  EXPECT_LT(error, 1e-5);
  single.backward();
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(single.output()[i] / static_cast<double>(rows * cols), x[i], 1e-6) << i;
  }
  fftwf_free(aligned);
  set_threads(threads_before);
}

// The transposed transform in parts (rows, columns a few at a time in any
// order, rows back) gives the whole transforms' spectrum and inverse, with
// column counts below, at and above the planned block and a remainder.
TEST(RealFftTest, ColumnsInPartsGiveTheWholeTransforms) {
  for (const auto& [rows, cols] :
       std::vector<std::pair<std::size_t, std::size_t>>{{2, 3}, {6, 8}, {17, 30}, {32, 40}, {9, 64}}) {
    const std::size_t n = rows * cols;
    RealFft whole(rows, cols, FftPlanning::estimate, FftOutput::overwrite_input, FftLayout::transposed);
    RealFft parts(rows, cols, FftPlanning::estimate, FftOutput::overwrite_input, FftLayout::transposed);
    ASSERT_TRUE(parts.columns_in_parts()) << rows << "x" << cols;
    double* values = fftw_alloc_real(n);
    const std::vector<double> x = random_values(n, static_cast<unsigned>(n));
    std::copy(x.begin(), x.end(), values);
    ASSERT_TRUE(parts.takes_input({values, n}));
    ASSERT_TRUE(parts.takes_output({values, n}));
    ASSERT_FALSE(parts.takes_input({values, n - 1}));
    ASSERT_TRUE(whole.forward_from({values, n}));
    parts.forward_rows_from({values, n});
    // From the last columns back, in groups of 3 (not the planned block) and
    // then the rest at once.
    const std::size_t columns = parts.spectrum_cols();
    std::size_t left = columns;
    for (; left > 3; left -= 3) parts.transform_columns(left - 3, 3, true);
    parts.transform_columns(0, left, true);
    for (std::size_t k = 0; k < parts.spectrum_size(); ++k) {
      ASSERT_LE(std::abs(parts.spectrum()[k] - whole.spectrum()[k]), 1e-14 * static_cast<double>(n))
          << rows << "x" << cols << " entry " << k;
    }
    parts.transform_columns(0, columns, false);
    parts.backward_rows_into({values, n});
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_NEAR(values[i] / static_cast<double>(n), x[i], 1e-14) << rows << "x" << cols << " at " << i;
    }
    fftw_free(values);
  }
}

// A transposed transform's spectrum against the row-major one's, and back:
// spectra past 16 MiB are scattered into their columns by streaming stores.
template <class Real>
void expect_transposed_equals_row_major(std::size_t n_side, unsigned seed, double spectrum_tolerance,
                                        double value_tolerance) {
  const std::size_t rows = n_side;
  const std::size_t cols = n_side;
  const std::size_t n = rows * cols;
  fft::BasicRealFft<Real> transposed(rows, cols, FftPlanning::estimate, FftOutput::overwrite_input,
                                     FftLayout::transposed);
  fft::BasicRealFft<Real> row_major(rows, cols, FftPlanning::estimate);
  ASSERT_GT(transposed.spectrum_size() * sizeof(std::complex<Real>), std::size_t{16} << 20);
  const std::vector<double> x = random_values(n, seed);
  std::copy(x.begin(), x.end(), transposed.input().begin());
  std::copy(x.begin(), x.end(), row_major.input().begin());
  transposed.forward();
  row_major.forward();
  const std::size_t h = cols / 2 + 1;
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < h; ++c) {
      ASSERT_LE(std::abs(transposed.spectrum()[c * rows + r] - row_major.spectrum()[r * h + c]), spectrum_tolerance)
          << "ky " << r << ", kx " << c;
    }
  }
  transposed.backward();
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NEAR(transposed.output()[i] / static_cast<Real>(n), x[i], value_tolerance) << "at " << i;
  }
}

// 1536 x 769 entries, 18.9 MB.
TEST(RealFftTest, LargeTransposedSpectraEqualTheRowMajorOnes) {
  expect_transposed_equals_row_major<double>(1536, 7, 1e-9, 1e-13);
}

// 2304 x 1153 entries, 21.2 MB.
TEST(RealFftTest, LargeTransposedSingleSpectraEqualTheRowMajorOnes) {
  expect_transposed_equals_row_major<float>(2304, 11, 2e-2, 1e-5);
}

TEST(RealFftTest, RejectsEmptySize) {
  EXPECT_THROW(RealFft(0, FftPlanning::estimate), InputError);
}

}  // namespace
}  // namespace halfspace
