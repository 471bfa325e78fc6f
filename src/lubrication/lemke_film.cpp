// The p–theta problem as Giacopini et al.'s (2010) LCP, assembled densely
// from the same stencil the projected SOR sweeps and solved by Lemke's method
// (the seed paper's dense path for contact). A, the Poiseuille matrix of the
// unknown nodes, is an M-matrix when some axis has fixed pressures, so it is
// inverted once by LU.
#include "halfspace/lubrication/lemke_film.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/solvers/lemke.hpp"

namespace halfspace::lubrication {

FilmSolution solve_film_lemke(const ReynoldsStencil& stencil) {
  if (stencil.time_rate() > 0.0) throw InputError("the dense film path solves the steady film only (no time term)");
  const std::size_t n = stencil.size();
  std::vector<Eigen::Index> unknown(n, -1);
  Eigen::Index count = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!stencil.fixed(k)) unknown[k] = count++;
  }
  if (static_cast<std::size_t>(count) > kMaxLemkeFilmNodes) {
    throw InputError(
        fmt::format("the dense film path takes at most {} unknown nodes; this grid has {}", kMaxLemkeFilmNodes, count));
  }
  const Eigen::ArrayXd& h = stencil.film();
  const double supply = stencil.conditions().boundary.supply_fluid_fraction;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(count, count);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(count, count);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(count);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Index row = unknown[k];
    if (row < 0) continue;
    const Neighbours nb = stencil.neighbours(k);
    const auto face = [&](std::size_t other, double conductance) {
      if (other == Neighbours::kNone) return;
      a(row, row) += conductance;
      if (stencil.fixed(other)) {
        b[row] += conductance * stencil.fixed_pressure(other);
      } else {
        a(row, unknown[other]) -= conductance;
      }
    };
    face(nb.west, nb.west != Neighbours::kNone ? stencil.east_conductance(nb.west) : 0.0);
    face(nb.east, stencil.east_conductance(k));
    face(nb.south, nb.south != Neighbours::kNone ? stencil.north_conductance(nb.south) : 0.0);
    face(nb.north, stencil.north_conductance(k));
    g(row, row) += (stencil.couette_x() + stencil.couette_y()) * h[k];
    const auto upstream = [&](std::size_t other, double coefficient) {
      if (other == Neighbours::kNone || coefficient == 0.0) return;
      if (stencil.fixed(other)) {
        b[row] += coefficient * h[other] * supply;
      } else {
        g(row, unknown[other]) -= coefficient * h[other];
      }
    };
    upstream(stencil.upstream_x(nb), stencil.couette_x());
    upstream(stencil.upstream_y(nb), stencil.couette_y());
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
  solvers::LcpProblem problem;
  problem.matrix = lu.solve(g);
  problem.offset = lu.solve(b - g * Eigen::VectorXd::Ones(count));
  const solvers::LcpSolution lcp =
      solvers::solve_lcp_lemke(problem, {.max_pivots = 50 * static_cast<int>(count) + 100});

  FilmSolution solution;
  solution.iterations = lcp.iterations;
  solution.pressure = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  solution.fluid_fraction = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), supply);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Index row = unknown[k];
    if (row < 0) {
      solution.pressure[k] = stencil.fixed_pressure(k);
    } else if (lcp.z.size() == count) {
      // w = p and z = 1 - theta; Lemke's complementary pair has w or z zero,
      // rounding may leave either a few ulps below it.
      solution.pressure[k] = std::max(lcp.w[row], 0.0);
      solution.fluid_fraction[k] = std::min(1.0, 1.0 - lcp.z[row]);
    }
  }
  solution.relative_residual = relative_mass_residual(stencil, solution.pressure, solution.fluid_fraction);
  if (!lcp.solved()) {
    solution.status =
        lcp.status == solvers::LcpStatus::iteration_limit ? FilmStatus::iteration_limit : FilmStatus::failure;
    solution.message =
        fmt::format("Lemke's method on the film LCP: {} ({})", solvers::to_string(lcp.status), lcp.message);
    return solution;
  }
  solution.status = FilmStatus::converged;
  return solution;
}

}  // namespace halfspace::lubrication
