// The outcome of a contact solve, returned as data: status, convergence
// record, integral quantities and the fields. Non-convergence is a status,
// never an exception.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace halfspace::solvers {

enum class SolveStatus {
  converged,        // residual below tolerance
  iteration_limit,  // stopped at max_iterations with residual above tolerance
  breakdown,        // the iteration could not continue (message says why)
  stopped,          // the caller's progress callback asked to stop (never converged)
};

std::string_view to_string(SolveStatus status);
// The status whose to_string is `name` (as result files store it), if any.
std::optional<SolveStatus> parse_solve_status(std::string_view name);

// What a progress callback tells the iteration (as Ceres' IterationCallback):
// go on, or stop cleanly with status `stopped`.
enum class IterationDecision { proceed, stop };
// Called once per iteration with (iteration, residual) on the calling thread,
// between iterations (so it may print); may be empty.
using ProgressCallback = std::function<IterationDecision(int iteration, double residual)>;

// Calls `progress` (if set) with (iteration, residual); true when it asked
// to stop.
bool stop_requested(const ProgressCallback& progress, int iteration, double residual);

// The end of an iterative solve at `iteration` with `residual`, shared by
// the solvers' loops: stopped (the caller asked, `stop`), converged
// (residual <= tolerance), breakdown (a non-finite residual) or
// iteration_limit (at max_iterations), with the message of all but converged
// in *message; nullopt while the iteration goes on.
std::optional<SolveStatus> stopping_status(double residual, double tolerance, int iteration, int max_iterations,
                                           std::string* message, bool stop = false);

// The coarser grids a MultilevelSolver solved first: how many, their
// iterations, and their K and M^-1 products each weighted by its grid's
// cells over the fine grid's (the fine-grid products they cost).
struct CoarseStart {
  int levels = 0;
  int iterations = 0;
  double operator_work = 0.0;
  double preconditioner_work = 0.0;
};

// The block-deflation coarse correction of the fine solve (BlockDeflation):
// block size (0: none), the iterations it was applied in, and its coarse
// work. declined counts the full builds not made because the contact was
// too dense; then the solve ran without it.
struct DeflationRecord {
  std::size_t block = 0;
  int deflated_iterations = 0;
  int rebuilds = 0;
  int updates = 0;
  int declined = 0;
  long coarse_iterations = 0;
  // Coarse solves that stopped short of their tolerance (iteration limit or
  // breakdown); each leaves the correction inexact, which SolveResult::warnings
  // reports.
  int unconverged_coarse_solves = 0;
  // The rate per iteration of the last two settled steps without the
  // correction, when it was measured and found fast (it then stays off):
  // 0 if never measured or if the correction joined.
  double fast_rate = 0.0;
};

// Adhesive solves (adhesive_contact_solver.hpp): the law and the adhesive
// quantities of the result; `law` is empty for every other solver.
struct AdhesionRecord {
  std::string law;                          // "md" or "exponential"
  double work = 0.0;                        // work of adhesion w, J/m^2
  double range = 0.0;                       // h0 (md) or rho (exponential), m
  double stress = 0.0;                      // w / range: sigma0 (md), the stress at contact (exponential), Pa
  double adhesive_force = 0.0;              // sum of the negative pressures times cell area (<= 0)
  double interaction_fraction = 0.0;        // cells within the law's range (AdhesionLaw::interacts)
  double repulsive_contact_fraction = 0.0;  // cells with gap 0 and pressure > 0
};

struct SolveResult {
  SolveStatus status = SolveStatus::breakdown;
  std::string message;  // human-readable reason, empty when converged
  std::string solver;   // e.g. "polonsky-keer"
  // Numerical trouble that did not stop the solve but may have slowed it or
  // made it less accurate (e.g. unconverged coarse solves of the deflation),
  // one sentence each; empty when there was none.
  std::vector<std::string> warnings;

  int iterations = 0;
  double residual = 0.0;                 // final value of the stopping measure
  double tolerance = 0.0;                // the tolerance it was compared with
  std::vector<double> residual_history;  // one entry per iteration
  int operator_applications = 0;         // number of K*p products
  int preconditioner_applications = 0;   // number of M^-1 g products (each one FFT pair)
  CoarseStart coarse;                    // coarse-grid start (MultilevelSolver); zero otherwise
  // The primal-dual active-set phase before Polonsky-Keer (active_set_start.hpp):
  // its set updates and conjugate-gradient iterations (the latter are also
  // in `iterations`, its products in the counts above); zero without it.
  int active_set_outer = 0;
  int active_set_inner = 0;
  DeflationRecord deflation;  // coarse-grid correction of the fine solve; block 0 without
  AdhesionRecord adhesion;    // adhesive solves only

  double approach = 0.0;          // rigid-body approach (m)
  double total_force = 0.0;       // N in 2D, N/m in 1D
  double mean_pressure = 0.0;     // total_force / domain area (Pa)
  double max_pressure = 0.0;      // Pa
  double contact_fraction = 0.0;  // cells with p > 0 over all cells
  // The hardness cap the solve honoured (interface_law.hpp), unset for
  // purely elastic contact; plastic_fraction counts the cells at it over
  // all cells (zero without a cap).
  std::optional<double> hardness;
  double plastic_fraction = 0.0;
  double wall_seconds = 0.0;

  // Fields with one entry per cell, (ny, nx) row-major.
  Eigen::ArrayXd pressure;      // Pa, >= 0 (signed under an adhesion law: negative is tensile)
  Eigen::ArrayXd displacement;  // m, K * pressure
  Eigen::ArrayXd gap;           // m, initial_gap + displacement - approach

  bool converged() const { return status == SolveStatus::converged; }
};

}  // namespace halfspace::solvers

// The library, its writers and front ends name these without the folder's
// namespace.
namespace halfspace {
using solvers::AdhesionRecord;
using solvers::CoarseStart;
using solvers::DeflationRecord;
using solvers::SolveResult;
using solvers::SolveStatus;
using solvers::to_string;
}  // namespace halfspace
