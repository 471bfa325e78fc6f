// The dry contact a mixed film's Newton solve starts from and takes its
// scales from (mixed_film.cpp: the pressure, its peak, the approach): the
// same for every solve on one grid at one loading, and a grid's speed
// continuation makes up to one solve per step, so it is solved once per
// grid and loading and kept through one solve_mixed_film call or Stribeck
// sweep (mixed_film_keep.hpp). On the measured window at 1024^2 the free
// grid's Polonsky–Keer solve took 7 to 8 s of every continuation step
// (docs/development-log.md, 2026-12-04, forty-fifth session). Private to
// the library.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::lubrication::detail {

// The dry contact of `gap` (this process's rows) on op's grid under
// `loading`, by Polonsky–Keer: in the projected form with the Fourier
// preconditioner where `op` is a homogeneous half-space's FFT operator on a
// 2D grid (as `solve --solver pk-fourier`; its grid's own transform works
// in the operator's idle buffer), in the paper's form otherwise (a coarse
// grid's R K P, a line, where the preconditioner cycles on measured
// profiles, and a coating, whose stiff layers it does not serve;
// solver_factory.cpp). On the measured window at 512^2: 25 iterations
// instead of 94 (docs/development-log.md, 2026-12-04, forty-seventh
// session). Collective on several processes.
solvers::SolveResult solve_dry_contact(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                       const solvers::Loading& loading);

class DryContactMemo {
 public:
  // The dry contact of `gap` (this process's rows) on op's grid under
  // `loading` (solve_dry_contact): the kept one where `op`, the gap's values
  // and the loading are the solve's kept for the grid's shape on every
  // process, else solved and kept in its place (a separation continuation
  // moves the approach at every step). An operator object is taken to stay
  // the same operator while the memo lives. Collective on several
  // processes. The reference holds until the memo goes; its values until
  // the next solve on a grid of the same shape.
  const solvers::SolveResult& solve(InfluenceOperator& op, const Eigen::ArrayXd& gap, const solvers::Loading& loading);

  // The Polonsky–Keer solves made (not the kept ones handed out).
  int solves() const { return solves_; }

 private:
  struct Kept {
    const InfluenceOperator* op = nullptr;
    std::size_t nx = 0, ny = 0;
    Eigen::ArrayXd gap;
    solvers::Loading loading;
    solvers::SolveResult result;
  };
  std::deque<Kept> kept_;  // one per grid shape; stable references
  int solves_ = 0;
};

}  // namespace halfspace::lubrication::detail
