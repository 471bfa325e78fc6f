// Grid sequencing for the EHL Newton iteration (nested iteration, Venner &
// Lubrecht 2000, ch. 3 "full multigrid"): the film solved on the grid of
// twice the spacing is interpolated onto the fine grid as its Newton start,
// so that the fine Newton iteration only corrects the discretisation
// difference. Private to the library.
#pragma once

#include <Eigen/Core>
#include <span>

#include "film_krylov_solver.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication::detail {

// The Newton iteration of solve_elastic_film on the operator's grid alone
// (no grid sequencing): from `start` if it holds a film of this grid, else
// from the dry contact (elastic_film.cpp).
ElasticFilm solve_film_newton(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                              const LubricantLaws& laws, const ElasticFilmOptions& options, const ElasticFilm* start);

// The GMRES settings of the options.
FilmKrylovSettings film_krylov_settings(const ElasticFilmOptions& options);

// Throws InputError naming the grid if the GMRES path's memory estimate
// (film_krylov_memory_estimate) exceeds the memory available.
void require_film_memory(const Grid& grid, const ElasticFilmOptions& options);

}  // namespace halfspace::lubrication::detail
