// The friction options of `halfspace solve` (--friction, --tangential-force,
// --tangential-displacement, --sliding, --tangential-tol, --tangential-max-iter) mapped onto the
// library's FrictionOptions, whose validate() holds the rules; a broken rule
// is restated with the flags (or config keys) it came from.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/solvers/friction_options.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "solve_options.hpp"

namespace halfspace::app {

// Tangential load steps as written: steps separated by ';', each "X" or
// "X,Y", or a range "START:STOP:COUNT" of COUNT >= 2 evenly spaced steps
// from START to STOP, both included, whose ends are "X" or "X,Y"
// ("0:1:5;1:-1:9"). Throws InputError naming `what` and the offending part.
std::vector<solvers::TangentialLoading> parse_tangential_steps(std::string_view text,
                                                               solvers::TangentialControl control,
                                                               std::string_view what);

// The friction options given, or none without --friction (then any other
// friction flag is refused). Checks what needs no surface: the flags given
// together, the steps' syntax, FrictionOptions::validate(), and the
// combinations the slice refuses (coating, E* alone, a load sweep, stress
// depths with a history, adhesion). On several processes the distributed
// layout refuses what it cannot run (mpi/distributed_layout.hpp).
std::optional<solvers::FrictionOptions> friction_from(const SolveOptions& options, bool coated,
                                                      std::size_t normal_load_steps);

// The checks that need the grid, the pair of bodies (E1, nu1, E2, nu2,
// checked by then) and the normal solve's settings
// (FrictionOptions::validate(grid, pair, normal, loading)).
void check_friction(const SolveOptions& options, const solvers::FrictionOptions& friction, const Grid& grid,
                    const ElasticPair& pair, const solvers::SolverOptions& normal, const Loading& loading);

}  // namespace halfspace::app
