#include "halfspace/fft/padded_real_fft.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/threads.hpp"

namespace halfspace {
namespace {

// Rounding of a few-hundred-point transform, relative to the largest value.
constexpr double kRounding = 1e-12;

std::vector<double> block_values(std::size_t rows, std::size_t cols) {
  std::vector<double> values(rows * cols);
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = std::sin(0.7 * static_cast<double>(k) + 0.3) + 0.25;
  return values;
}

// The DFT of the zero-padded block by its definition, at padded wavenumber (kr, kc).
std::complex<double> direct_dft(const std::vector<double>& block, std::size_t rows, std::size_t cols, std::size_t kr,
                                std::size_t kc) {
  const std::size_t padded_rows = rows == 1 ? 1 : 2 * rows;
  std::complex<double> sum = 0.0;
  for (std::size_t j = 0; j < rows; ++j) {
    for (std::size_t i = 0; i < cols; ++i) {
      const double angle = -2.0 * std::numbers::pi *
                           (static_cast<double>(kr * j) / static_cast<double>(padded_rows) +
                            static_cast<double>(kc * i) / static_cast<double>(2 * cols));
      sum += block[j * cols + i] * std::polar(1.0, angle);
    }
  }
  return sum;
}

TEST(PaddedRealFftTest, ForwardIsTheDftOfTheZeroPaddedBlock) {
  // 17 and 9 rows: a part block of rows (16 per block) in each direction.
  for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{1, 9}, {5, 6}, {4, 7}, {17, 5}, {9, 3}}) {
    SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols));
    PaddedRealFft fft(rows, cols, FftPlanning::estimate);
    ASSERT_EQ(fft.transposed(), rows > 1);
    ASSERT_EQ(fft.spectrum_rows(), rows == 1 ? 1u : 2 * rows);
    ASSERT_EQ(fft.spectrum_cols(), cols + 1);
    const std::vector<double> block = block_values(rows, cols);
    fft.forward(block);
    const std::span<const std::complex<double>> spectrum = fft.spectrum();
    for (std::size_t kr = 0; kr < fft.spectrum_rows(); ++kr) {
      for (std::size_t kc = 0; kc < fft.spectrum_cols(); ++kc) {
        const std::complex<double> expected = direct_dft(block, rows, cols, kr, kc);
        const std::size_t k = fft.transposed() ? kc * fft.spectrum_rows() + kr : kr * fft.spectrum_cols() + kc;
        EXPECT_LE(std::abs(spectrum[k] - expected), kRounding * static_cast<double>(block.size())) << kr << ", " << kc;
      }
    }
  }
}

TEST(PaddedRealFftTest, BackwardOfForwardReturnsTheBlockTimesThePaddedSize) {
  for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{1, 16}, {6, 10}, {7, 5}, {33, 4}}) {
    SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols));
    PaddedRealFft fft(rows, cols, FftPlanning::estimate);
    const std::vector<double> block = block_values(rows, cols);
    std::vector<double> back(block.size(), -99.0);
    // Twice: the padding rows' spectra must be cleared again after backward() used the buffer.
    for (int pass = 0; pass < 2; ++pass) {
      fft.forward(block);
      fft.backward(back);
      const double n = static_cast<double>(fft.padded_size());
      for (std::size_t k = 0; k < block.size(); ++k) EXPECT_NEAR(back[k] / n, block[k], kRounding) << k;
    }
  }
}

TEST(PaddedRealFftTest, AllRowsTransformMatchesThePrunedOneOnABlock) {
  // A full padded array whose rows beyond the block are zero: the same
  // spectrum as forward() of the block; filled a block of rows at a time,
  // on one and on two threads.
  const int threads_before = threads();
  for (const int team : {1, 2}) {
    set_threads(team);
    for (const auto& [rows, cols] : {std::pair<std::size_t, std::size_t>{4, 6}, {9, 5}, {1, 7}}) {
      SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols));
      PaddedRealFft fft(rows, cols, FftPlanning::estimate);
      const std::vector<double> block = block_values(rows, cols);
      fft.forward(block);
      const std::vector<std::complex<double>> pruned(fft.spectrum().begin(), fft.spectrum().end());
      fft.forward_rows([&](std::size_t first, std::size_t count, const PaddedRealFft::Row& row) {
        for (std::size_t i = 0; i < count; ++i) {
          const std::size_t r = first + i;
          const std::span<double> values = row(i);
          ASSERT_EQ(values.size(), 2 * cols);
          for (std::size_t c = 0; c < values.size(); ++c) values[c] = r < rows && c < cols ? block[r * cols + c] : 0.0;
        }
      });
      for (std::size_t k = 0; k < pruned.size(); ++k) {
        EXPECT_LE(std::abs(fft.spectrum()[k] - pruned[k]), kRounding * static_cast<double>(block.size())) << k;
      }
    }
  }
  set_threads(threads_before);
}

}  // namespace
}  // namespace halfspace
