// One load step of the coupled normal-tangential problem of elastically
// dissimilar bodies (Dundurs' beta != 0; docs/theory.md, "Friction",
// "Coupled normal and tangential problems"): the pressure p and the shear q
// with the normal conditions
//   g = g0 + K p + K_c^T q - approach >= 0,  p >= 0,  p g = 0,
// and the Coulomb conditions of tangential_solver.hpp for the tangential
// displacement C q + K_c p (K_c the coupling, TangentialOperator::
// apply_pressure_coupling, K_c^T apply_traction_coupling), both together.
// Solved by alternation (the Panagiotopoulos process, Panagiotopoulos 1975;
// Kalker 1990, sec. 5.5): the normal problem under the last shear's normal
// displacement, then the tangential step under that pressure and its
// tangential displacement, until the shear's change moves the surfaces
// normally by at most `tolerance` of the normal displacement. The
// tangential conditions then hold for the returned (p, q) to the tangential
// solver's tolerance and the normal ones to this one's; not converging
// (the alternation contracts by about |beta| mu per pass) is reported.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <string>

#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "halfspace/solvers/tangential_solver.hpp"

namespace halfspace::solvers {

struct CoupledStepOptions {
  double tolerance = 1e-6;  // of the normal displacement the shear's last change makes, relative
  int max_alternations = 100;
  // Throws SolverOptionError (an InputError) unless 0 < tolerance < 1
  // ("coupling_tolerance") and max_alternations >= 1 ("max_alternations").
  void validate() const;
};

struct CoupledStepResult {
  SolveResult normal;  // p; displacement K p + K_c^T q (the shear's part included), gap with it
  TangentialResult tangential;
  int alternations = 0;
  double coupling_residual = 0.0;  // the last pass's change of K_c^T q over max |K p|
  int tangential_iterations = 0;   // over all alternations (tangential.iterations is the last one's)
  SolveStatus status = SolveStatus::breakdown;
  std::string message;  // why it stopped, empty when converged

  bool converged() const { return status == SolveStatus::converged; }
};

class CoupledStepSolver {
 public:
  // Keeps references to the three (which must outlive it); `tangential`
  // must have been built on `op`. Allocates its workspace once.
  CoupledStepSolver(ContactSolver& normal, TangentialOperator& op, TangentialSolver& tangential,
                    CoupledStepOptions options);

  // The step from `previous` under `normal_loading` and `loading` (or, with
  // `sliding` set, the force mu P along that direction, P the current
  // pressure's), the normal solves warm-started from `start_pressure` (or
  // empty). Throws InputError for sizes that do not match the grid and what
  // the two solvers throw.
  CoupledStepResult solve(std::span<const double> initial_gap, const Loading& normal_loading,
                          const TangentialLoading& loading, const TangentialState& previous,
                          std::span<const double> start_pressure,
                          const std::optional<std::array<double, 2>>& sliding = std::nullopt);

 private:
  ContactSolver& normal_;
  TangentialOperator& op_;
  TangentialSolver& tangential_;
  CoupledStepOptions options_;
  // The normal displacement of the shear the last normal solve saw and of
  // the new shear, the gap with the first, the pressure's tangential
  // displacement.
  Eigen::ArrayXd w_, w_new_, gap_, vx_, vy_;
};

}  // namespace halfspace::solvers

namespace halfspace {
using solvers::CoupledStepOptions;
using solvers::CoupledStepResult;
using solvers::CoupledStepSolver;
}  // namespace halfspace
