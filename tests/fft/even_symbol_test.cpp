#include "halfspace/fft/even_symbol.hpp"

#include <gtest/gtest.h>

#include <complex>
#include <vector>

namespace halfspace {
namespace {

// Row r and row rows - r share their values; every other entry is its own.
TEST(EvenSymbolTest, FoldsRowsOntoTheirMirror) {
  for (const std::size_t rows : {1u, 2u, 5u, 6u}) {
    SCOPED_TRACE(rows);
    const EvenSymbol symbol(rows, 3);
    EXPECT_EQ(symbol.stored_rows(), rows == 1 ? 1u : rows / 2 + 1);
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t expected = r <= rows / 2 ? r : rows - r;
      EXPECT_EQ(symbol.folded(r), expected) << "row " << r;
    }
  }
}

TEST(EvenSymbolTest, MultipliesEachRowByItsFoldedRow) {
  const std::size_t rows = 5;
  const std::size_t cols = 4;
  EvenSymbol symbol(rows, cols);
  for (std::size_t r = 0; r < symbol.stored_rows(); ++r) {
    for (std::size_t c = 0; c < cols; ++c) symbol.at(r, c) = 10.0 * static_cast<double>(r) + static_cast<double>(c);
  }
  std::vector<std::complex<double>> spectrum(rows * cols, {1.0, -2.0});
  symbol.multiply(spectrum);
  for (std::size_t r = 0; r < rows; ++r) {
    const double row_value = 10.0 * static_cast<double>(r <= 2 ? r : rows - r);
    for (std::size_t c = 0; c < cols; ++c) {
      const double value = row_value + static_cast<double>(c);
      EXPECT_EQ(spectrum[r * cols + c], std::complex<double>(value, -2.0 * value)) << r << ", " << c;
    }
  }
}

}  // namespace
}  // namespace halfspace
