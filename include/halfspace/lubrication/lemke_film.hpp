// The dense path for small grids: the p–theta problem written as the LCP of
// Giacopini et al. (2010, J. Tribol. 132, 041702) and solved by Lemke's
// method, a cross-check of the projected SOR.
#pragma once

#include <cstddef>

#include "halfspace/lubrication/film_solution.hpp"
#include "halfspace/lubrication/reynolds_stencil.hpp"

namespace halfspace::lubrication {

// Unknown nodes up to which the dense path is allowed (its matrix is n x n).
inline constexpr std::size_t kMaxLemkeFilmNodes = 2500;

// With r = 1 - theta, the stencil's balance A p + G theta = b gives
// p = A^-1 (b - G 1) + A^-1 G r: the LCP  w = M r + q >= 0, r >= 0,
// r' w = 0 with w = p (every node's p > 0 or theta < 1, never both). Throws
// InputError above kMaxLemkeFilmNodes unknown nodes; a ray or the pivot
// limit is a status.
FilmSolution solve_film_lemke(const ReynoldsStencil& stencil);

}  // namespace halfspace::lubrication
