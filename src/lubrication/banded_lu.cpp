// Banded LU with partial pivoting (banded_lu.hpp), the column-oriented
// algorithm of LAPACK's dgbtf2: pivoting within a column's kl subdiagonal
// entries lets U grow to kl + ku superdiagonals, which the storage holds.
#include "banded_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace halfspace::lubrication::detail {

bool banded_lu_factorise(std::span<double> band, std::span<int> pivots, int kl, int ku) {
  const std::size_t n = pivots.size();
  const auto at = [&](std::size_t i, std::size_t j) -> double& { return band[banded_index(kl, ku, i, j)]; };
  std::size_t last_column = 0;  // the rightmost column U reaches so far
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t below = std::min(static_cast<std::size_t>(kl), n - 1 - j);
    std::size_t pivot_row = j;
    for (std::size_t i = j + 1; i <= j + below; ++i) {
      if (std::abs(at(i, j)) > std::abs(at(pivot_row, j))) pivot_row = i;
    }
    pivots[j] = static_cast<int>(pivot_row);
    if (at(pivot_row, j) == 0.0) return false;
    last_column = std::max(last_column, std::min(j + static_cast<std::size_t>(ku) + (pivot_row - j), n - 1));
    if (pivot_row != j) {
      for (std::size_t c = j; c <= last_column; ++c) std::swap(at(j, c), at(pivot_row, c));
    }
    const double inverse = 1.0 / at(j, j);
    for (std::size_t i = j + 1; i <= j + below; ++i) at(i, j) *= inverse;
    for (std::size_t c = j + 1; c <= last_column; ++c) {
      const double u = at(j, c);
      if (u == 0.0) continue;
      for (std::size_t i = j + 1; i <= j + below; ++i) at(i, c) -= at(i, j) * u;
    }
  }
  return true;
}

void banded_lu_solve(std::span<const double> band, std::span<const int> pivots, int kl, int ku, std::span<double> rhs) {
  const std::size_t n = pivots.size();
  const auto at = [&](std::size_t i, std::size_t j) { return band[banded_index(kl, ku, i, j)]; };
  // L y = P b, the interchanges applied as the factorisation made them.
  for (std::size_t j = 0; j < n; ++j) {
    const auto p = static_cast<std::size_t>(pivots[j]);
    if (p != j) std::swap(rhs[j], rhs[p]);
    const std::size_t below = std::min(static_cast<std::size_t>(kl), n - 1 - j);
    const double y = rhs[j];
    for (std::size_t i = j + 1; i <= j + below; ++i) rhs[i] -= at(i, j) * y;
  }
  // U x = y, U with kl + ku superdiagonals.
  const auto upper = static_cast<std::size_t>(kl + ku);
  for (std::size_t j = n; j-- > 0;) {
    rhs[j] /= at(j, j);
    const double x = rhs[j];
    const std::size_t above = std::min(upper, j);
    for (std::size_t i = j - above; i < j; ++i) rhs[i] -= at(i, j) * x;
  }
}

}  // namespace halfspace::lubrication::detail
