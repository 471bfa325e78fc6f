// Grid sequencing for the mixed film (mixed_film_grid_sequence.cpp): the
// film on a grid solved first on the grid of twice the spacing and
// interpolated as the fine Newton start. Private to the library.
#pragma once

#include <Eigen/Core>

#include "halfspace/lubrication/mixed_film.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "mixed_film_keep.hpp"

namespace halfspace::lubrication::detail {

// How solve_mixed_film_on_grid uses its start: the Newton iteration from it
// and, where that fails, the continuations solve_mixed_film documents; the
// Newton iteration alone; or (a converged start at another speed) the
// continuation in the speed from it alone.
// try_only: solve_only, giving up where the Newton iteration stagnates or a
// step's GMRES stops short of its forcing term (the fine grid's first try
// from the coarse film, which has a way round); try_until_short: giving up
// only where a step's GMRES stops short (the same try on the larger grids,
// where a try that converges may stagnate first); solve_as_start:
// solve_only, the film only the next solve's start (FilmTolerances::
// start_norm_share = kStartNormShare); try_as_start: try_until_short on
// such a film (a grid-sequenced start in full film).
enum class MixedStartUse {
  solve_then_continue,
  solve_only,
  try_only,
  try_until_short,
  continue_only,
  solve_as_start,
  try_as_start
};

// solve_mixed_film with what its solves keep in `keep` (mixed_film_keep.hpp):
// a Stribeck sweep's points share it.
MixedFilm solve_mixed_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, MixedFilmKeep& keep,
                           const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                           const MixedFilm* start = nullptr);

// The mixed film on the operator's grid alone (no coarser grid): the Newton
// iteration from `start` or the standard starts (mixed_film.cpp) and the
// continuations, as `use` says. Each Newton solve takes its dry contact
// (solved there once for the grid and loading) and its GMRES basis from
// `keep`.
MixedFilm solve_mixed_film_on_grid(InfluenceOperator& op, const Eigen::ArrayXd& gap, MixedFilmKeep& keep,
                                   const FlowConditions& conditions, const LubricantLaws& laws,
                                   const MixedFilmOptions& options, const MixedFilm* start,
                                   MixedStartUse use = MixedStartUse::solve_then_continue);

// The mixed film from the converged film `start` (of the same grid, at
// another speed or load) with its contact rows smoothed (mixed_film.cpp),
// the smoothing followed down to the film itself; where a plain Newton
// iteration stalls in the transition between the full film and the
// contact.
MixedFilm solve_mixed_film_smoothed(InfluenceOperator& op, const Eigen::ArrayXd& gap, MixedFilmKeep& keep,
                                    const FlowConditions& conditions, const LubricantLaws& laws,
                                    const MixedFilmOptions& options, const MixedFilm& start);

// The relative mass residual and load error to which the speed
// continuation solves a film between in full film (the last film carries no
// contact load; its contact rows to a hundredth of it): that film is only
// the next step's start. On the measured window (docs/development-log.md,
// 2026-12-03, fortieth session) the full-film films between took 0 to 3
// Newton steps instead of 4 to 7 (at 1024^2 1e-3 still took 3 or 4: the
// largest mass residual falls slowly there while the residual's norm falls
// 30-fold in a step). In the mixed regime the films between are solved as
// the answer is: at 32^2 a loose one sent the continuation through 20
// solves instead of 7.
inline constexpr double kFullFilmStartTolerance = 3e-3;
// Such a film is also taken where a Newton step has lowered the residual's
// norm to a tenth of its first value (with the relative residuals within
// the check's allowance, ten times the start tolerance). At 1024^2 the
// first step lowered it 20- to 60-fold, and the largest mass residual then
// took 1 or 2 more steps (29 to 87 s each) to fall below the start
// tolerance (docs/development-log.md, 2026-12-03, forty-first session).
// The film before the last, the answer's start, is solved without it
// (mixed_film.cpp, continue_in_speed).
inline constexpr double kStartNormShare = 0.1;

// `options` with the tolerances of a film in full film that is only the
// next solve's start: the mass residual and the load error to
// kFullFilmStartTolerance, the contact rows to a hundredth of it (the
// speed continuation's films between, a grid-sequenced start's fine grid).
MixedFilmOptions full_film_start_options(const MixedFilmOptions& options);

// `conditions` with the entrainment and sliding velocities times `factor`.
FlowConditions at_speed_factor(const FlowConditions& conditions, double factor);

}  // namespace halfspace::lubrication::detail
