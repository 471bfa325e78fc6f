// The load search of load_control.cpp over any film a separation makes: the
// steady rigid film, or one step of the transient film (transient_film.cpp).
#pragma once

#include <functional>

#include "halfspace/lubrication/load_control.hpp"

namespace halfspace::lubrication {

// The film at a separation, warm-started from `start` (null: cold).
using FilmAtSeparation = std::function<LubricatedFilm(double separation, const FilmSolution* start)>;

// The separation at which `solve` carries load.load, starting from
// `initial_separation` (> 0); the rules and outcomes of lubricate_at_load.
LubricatedFilm search_separation_for_load(const LoadControlOptions& load, double initial_separation,
                                          const FilmAtSeparation& solve);

}  // namespace halfspace::lubrication
