// Partial slip under Coulomb friction under a given pressure p (for
// elastically similar bodies, Dundurs' beta = 0, the normal solve's; for
// dissimilar ones one half of the alternation of coupled_step.hpp, which
// passes the pressure's tangential displacement K p as the step's fixed
// part): given p, the previous step's state and a tangential load step,
// the shear q with
//   |q_i| <= mu p_i in every cell (q = 0 out of contact),
//   stick: ds_i = 0,  slip: |q_i| = mu p_i and q_i = -mu p_i ds_i / |ds_i|,
// where ds = C q + v - u_prev - (delta - delta_prev) is the slip increment
// (u_prev the previous step's whole displacement, v the fixed part, zero
// without coupling, so that ds = C (q - q_prev) - (delta - delta_prev)).
// These are the optimality conditions of the convex problem on a product of
// discs (docs/theory.md, "Friction")
//   minimise 1/2 q.C q - q.(C q_prev + delta - delta_prev)  over |q_i| <= mu p_i,
// with, under force control, sum_i q_i A_cell = Q and delta its multiplier.
// Two methods (TangentialMethod): by default preconditioned conjugate
// gradients on the stick/slip sets in Polonsky & Keer's manner, stick cells
// free in both components, slipping cells only along their circle (with its
// curvature), the sets updated every iteration and the directions
// preconditioned by the inverse of C's Fourier symbol
// (TangentialOperator::apply_approximate_inverse); or accelerated projected
// gradients (FISTA with adaptive restart, step 1/L with L the operator's
// eigenvalue bound), slower but with a convergence guarantee, which also
// takes over when the conjugate gradients stall. Both project
// onto the discs and, under force control, onto the force (every cell
// shifted alike, then clipped: the exact Euclidean projection).
//
// Stopping measure (the duality gap of the maximum-dissipation principle,
// zero exactly when the conditions hold, checked on an exact product):
//   residual = sum_i (mu p_i |ds_i| + q_i . ds_i) / (sum_i mu p_i  s_ref),
//   s_ref = max_i |u_i - u_prev_i| + |delta - delta_prev|,
// each term non-negative for admissible q (stick cells count their slip
// times their margin below mu p, slip cells the misalignment of q and ds).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/solver_options.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::solvers {

enum class TangentialMethod {
  conjugate_gradient,  // preconditioned, on the stick/slip sets (default)
  projected_gradient,  // FISTA with restart, unpreconditioned
};

// TangentialOptions::coarse_start.
enum class TangentialCoarseStart { off, on, automatic };

struct TangentialOptions {
  double friction_coefficient = 0.0;  // mu, >= 0 and finite
  double tolerance = 1e-6;            // of the residual above
  int max_iterations = 10000;
  TangentialMethod method = TangentialMethod::conjugate_gradient;
  // Conjugate gradients: a slipping cell whose multiplier turned negative is
  // released to the stick set only every this many iterations and held on
  // its circle between (1: every iteration). Releasing at every iteration,
  // cells whose multiplier flips sign from one iteration to the next swing
  // between the sets and the iteration cycles on large rough contacts
  // (docs/development-log.md, "releases held"). >= 1.
  int release_period = 5;
  // Conjugate gradients: each step is first solved on the grid of twice the
  // spacing (recursively, down to kCoarseStartMinCellsPerAxis cells per
  // axis, to coarse_tolerance), its traction prolonged as the fraction of
  // the disc each coarse cell uses (q / mu p, so that slip directions carry
  // over and the fine start is admissible), as pk-multilevel starts the
  // normal problem. Serial even grids without a fixed displacement.
  // automatic (the default) and on: wherever it applies (on the benchmark's
  // rough periodic contact it cut the first step's products by 19 %, 11 %,
  // 0 % and 15 % at 256^2, 512^2, 1024^2 and 2048^2 against the fine start,
  // with the stall rule's short window after it; docs/development-log.md,
  // 2026-11-30, branch fric29h); off: the fine start.
  TangentialCoarseStart coarse_start = TangentialCoarseStart::automatic;
  // Whether the coarse start is wanted (its other conditions aside).
  bool coarse_start_wanted() const { return coarse_start != TangentialCoarseStart::off; }
  // Of the coarse solves (the fine one's if tighter), in (0, 1): on the
  // benchmark's 1024^2 contact 1e-2, 1e-3, 1e-4 gave 139, 132, 154 fine
  // products' worth for the first step (docs/development-log.md).
  double coarse_tolerance = 1e-3;
  // Conjugate gradients: at most this many updates of an active-set
  // (semi-smooth Newton) phase before them, 0 for none: the stick set and
  // the slipping cells' directions held while preconditioned conjugate
  // gradients solve the linear problem on the stick cells, then the sets
  // and directions updated from the slip increment; the conjugate
  // gradients finish from where the sets settle (tangential_active_set.hpp).
  // Off by default: on the benchmark's rough contact it cost 65, 104, 165
  // products for the first step at 256^2, 512^2, 1024^2 against 66, 100,
  // 159 without, and 439 against 273 at 2048^2, where the sets took 27
  // updates to settle (docs/development-log.md, 2026-11-29, tang4). >= 0.
  int active_set_updates = 0;
  // Conjugate gradients: mixed, the direction's product C d and the
  // preconditioner through single-precision transforms where the operator
  // has them (TangentialOperator::single_precision(): serial periodic 2D
  // grids), their errors corrected by the exact double product C q every few
  // steps and always before the stop, whose duality gap is measured in
  // double; double_precision: every product in double.
  Precision precision = Precision::mixed;
  // Called once per iteration with (iteration, residual); may be empty or stop the solve.
  ProgressCallback progress;

  // Throws SolverOptionError (an InputError) naming the member ("friction"
  // for mu) unless mu is finite and >= 0, 0 < tolerance < 1,
  // max_iterations >= 1, release_period >= 1, active_set_updates >= 0,
  // 0 < coarse_tolerance < 1 and method, coarse_start and precision are
  // named values.
  void validate() const;
};

class TangentialSolver {
 public:
  // Keeps a reference to `op` (which must outlive the solver), allocates the
  // workspace once; solve() allocates nothing inside its loop. Throws
  // InputError if the options are invalid. For a dissimilar pair it solves
  // the tangential half of the coupled problem (the pressure given).
  TangentialSolver(TangentialOperator& op, TangentialOptions options);

  // One load step from `previous` (TangentialState::unloaded for the first)
  // under the pressure `pressure` (Pa, the normal solve's). Throws InputError
  // if a field has the wrong size, the pressure is negative or not finite,
  // the loading is not finite, or a force exceeds mu P (the contact slides:
  // impose a displacement instead). A force of exactly mu P (to 1e-9) is
  // gross sliding: every contact cell at mu p along Q, delta the smallest
  // approach at which every cell slips forward.
  TangentialResult solve(std::span<const double> pressure, const TangentialLoading& loading,
                         const TangentialState& previous);
  // The same with a fixed tangential displacement (fixed_x, fixed_y) (m, one
  // per cell, or both empty for none) added to C q: the coupling
  // displacement K p of the pressure (TangentialOperator::
  // apply_pressure_coupling). The result's displacement is then C q plus it.
  TangentialResult solve(std::span<const double> pressure, const TangentialLoading& loading,
                         const TangentialState& previous, std::span<const double> fixed_x,
                         std::span<const double> fixed_y);

  const TangentialOptions& options() const { return options_; }
  // The residual tolerance of the next solves (the coupled step tightens it
  // when its alternation stalls on the tangential solves' noise). Throws
  // InputError unless 0 < tolerance < 1.
  void set_tolerance(double tolerance);

  // No coarse grid is made with fewer cells than this along an axis.
  static constexpr std::size_t kCoarseStartMinCellsPerAxis = 32;

 private:
  // TangentialOptions::coarse_start: solves the step on the coarser grid
  // (itself started so) and leaves the prolonged fraction q / mu p in
  // tx_, ty_; false (and nothing written) if there is no coarser grid or
  // its solve failed. Adds the coarse work to `record`.
  bool coarse_start(std::span<const double> pressure, const TangentialLoading& loading, const TangentialState& previous,
                    CoarseStart& record);

  TangentialOperator& op_;
  TangentialOptions options_;
  Eigen::ArrayXd radius_;  // mu p
  // The cells in contact (mu p > 0), ascending: the iteration's passes run
  // over these alone (tangential_iteration.hpp, Problem::contact).
  std::vector<std::size_t> contact_;
  // The slip increment (and, within a conjugate-gradient step, C times the
  // direction), then workspace: the methods' search direction and previous
  // iterate or preconditioned gradient.
  Eigen::ArrayXd gx_, gy_, tx_, ty_, rx_, ry_;
  std::vector<std::uint8_t> kind_;  // conjugate gradients: each cell's set within a step
  // The active-set phase (active_set_updates > 0): each slipping cell's
  // tangential motion and curvature within an outer iteration.
  std::vector<float> tangent_motion_, curvature_;
  Eigen::ArrayXd fx_, fy_;  // the previous displacement less the fixed part (made on the first coupled solve)
};

}  // namespace halfspace::solvers

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using solvers::TangentialCoarseStart;
using solvers::TangentialMethod;
using solvers::TangentialOptions;
using solvers::TangentialSolver;
}  // namespace halfspace
