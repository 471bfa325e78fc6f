// LU factorisation with partial pivoting of a banded matrix (kl sub- and ku
// super-diagonals) and its solve, in the band storage of LAPACK's dgbtrf
// (Golub & Van Loan 2013, sec. 4.3): the line solves of the EHL multigrid
// smoother (film_multigrid.hpp). Private to the library.
#pragma once

#include <cstddef>
#include <span>

namespace halfspace::lubrication::detail {

// Doubles of band storage per row of an n x n matrix with kl sub- and ku
// super-diagonals: the band plus kl rows for the pivoting's fill.
inline std::size_t banded_lu_stride(int kl, int ku) {
  return static_cast<std::size_t>(2 * kl + ku + 1);
}

// A(i, j) for |i - j| within the band lives at band[j * stride + kl + ku + i - j].
inline std::size_t banded_index(int kl, int ku, std::size_t i, std::size_t j) {
  return j * banded_lu_stride(kl, ku) + static_cast<std::size_t>(kl + ku) + i - j;
}

// Factorises the n x n band matrix in `band` (n * stride values, the fill
// rows zero) in place, recording the row interchanges in `pivots`. Returns
// false if a pivot is exactly zero (the matrix is singular).
bool banded_lu_factorise(std::span<double> band, std::span<int> pivots, int kl, int ku);

// Solves A x = rhs in place with the factors of banded_lu_factorise.
void banded_lu_solve(std::span<const double> band, std::span<const int> pivots, int kl, int ku, std::span<double> rhs);

}  // namespace halfspace::lubrication::detail
