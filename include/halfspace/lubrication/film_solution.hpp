// A solved film: pressure and fluid fraction on the grid's nodes, and how the
// solver ended. Non-convergence is a status, never an exception.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>

namespace halfspace::lubrication {

enum class FilmStatus {
  converged,        // the mass balance and the complementarity conditions hold to the tolerance
  iteration_limit,  // stopped at the iteration limit before they did
  failure,          // the method failed (the message says how)
};

std::string_view to_string(FilmStatus status);

struct FilmSolution {
  FilmStatus status = FilmStatus::failure;
  std::string message;            // empty when converged
  Eigen::ArrayXd pressure;        // Pa, >= 0 (the cavitation pressure is 0), (ny, nx) row-major
  Eigen::ArrayXd fluid_fraction;  // theta in [0, 1]; 1 wherever p > 0
  int iterations = 0;             // sweeps (projected SOR) or pivots (Lemke)
  // Largest |mass balance| over the unknown nodes divided by the balance
  // scale (ReynoldsStencil::balance_scale), measured after the solve.
  double relative_residual = 0.0;

  bool converged() const { return status == FilmStatus::converged; }
};

}  // namespace halfspace::lubrication
