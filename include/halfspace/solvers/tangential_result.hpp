// The state a tangential load step leaves, which the next step starts from,
// and the outcome of the step (status, convergence record, integrals).
// Signs (docs/theory.md, "Friction"): the shear q is the traction body 1
// exerts on body 2 (Pa); the tangential displacement u = C q the relative
// elastic displacement of body 2's surface against body 1's (m); the approach
// delta the rigid displacement of body 1 against body 2 (m); the slip
// s = u - delta + const, accumulated over the steps a cell stays in contact
// (m), the motion of body 2's surface relative to body 1's; where a cell
// slips, q = -mu p ds/|ds|.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

struct TangentialState {
  Eigen::ArrayXd shear_x, shear_y;                // q, Pa
  Eigen::ArrayXd displacement_x, displacement_y;  // u = C q, m
  Eigen::ArrayXd slip_x, slip_y;                  // accumulated slip, m (0 out of contact)
  double approach_x = 0.0;                        // delta, m
  double approach_y = 0.0;

  // No traction, no slip: the start of a history on `cells` cells.
  static TangentialState unloaded(std::size_t cells);
  std::size_t size() const { return static_cast<std::size_t>(shear_x.size()); }
};

struct TangentialResult {
  SolveStatus status = SolveStatus::breakdown;
  std::string message;  // why it stopped, empty when converged
  TangentialState state;
  Eigen::ArrayXd stick;  // 1 where a contact cell sticks (|q| < mu p), else 0

  double friction_coefficient = 0.0;
  double force_x = 0.0;  // sum of q times cell area, N (N/m in 1D)
  double force_y = 0.0;
  double normal_force = 0.0;       // sum of p times cell area, the P of mu P
  double stick_fraction = 0.0;     // stick cells over contact cells
  double slip_fraction = 0.0;      // slipping cells over contact cells (1 - stick_fraction)
  double dissipated_energy = 0.0;  // sum over cells of -q . ds times cell area in this step, J (J/m in 1D)
  bool gross_sliding = false;      // every contact cell at |q| = mu p

  int iterations = 0;
  double residual = 0.0;  // the stopping measure (tangential_solver.hpp)
  double tolerance = 0.0;
  std::vector<double> residual_history;
  int operator_applications = 0;        // products u = C t
  int preconditioner_applications = 0;  // products t = M u (conjugate gradients)
  // The coarser grids solved first (TangentialOptions::coarse_start): their
  // iterations, and their products C and M weighted by their cells over
  // this grid's (the fine products they cost); not in the counts above.
  CoarseStart coarse;
  // The active-set phase (TangentialOptions::active_set_updates): its set
  // updates and inner conjugate-gradient iterations (the latter counted in
  // `iterations`, its products in the counts above).
  int active_set_updates = 0;
  int active_set_iterations = 0;
  double wall_seconds = 0.0;
  // Coupled steps of dissimilar bodies (coupled_step.hpp): the normal and
  // tangential solves alternated, and the last pass's change (zero both
  // when uncoupled; iterations and products above are the last pass's).
  int coupling_alternations = 0;
  int coupling_tangential_iterations = 0;  // the tangential iterations of every pass
  double coupling_residual = 0.0;
  double dundurs_beta = 0.0;  // of the pair the step was solved for
  bool coupled = false;       // solved coupled with the normal problem (beta != 0 and coupling on)

  bool converged() const { return status == SolveStatus::converged; }
};

}  // namespace halfspace::solvers

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using solvers::TangentialResult;
using solvers::TangentialState;
}  // namespace halfspace
