// The front door of the solvers: which solver, and every option it takes,
// typed and checked in one place (validate), so that a front end maps its
// own flags onto SolverOptions and adds no rule of its own. make_solver
// (solver_factory.hpp) builds the solver these options describe.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/active_set_options.hpp"
#include "halfspace/solvers/adhesion_law.hpp"
#include "halfspace/solvers/block_deflation_options.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

enum class SolverType {
  pk_multilevel,  // pk_fourier started from coarse-grid solutions (multilevel_solver.hpp)
  pk_fourier,     // Polonsky-Keer with the Fourier preconditioner (fourier_preconditioner.hpp)
  pk,             // Polonsky-Keer as the paper states it (polonsky_keer.hpp)
  lemke,          // Lemke pivoting on the assembled matrix, small grids (lemke.hpp)
  lcpquad,        // the paper's quadratic programme on the assembled matrix, small grids (lcp_quad.hpp)
};

// "pk-multilevel", "pk-fourier", "pk", "lemke", "lcpquad".
std::string_view to_string(SolverType type);
// The inverse of to_string; throws SolverOptionError naming the option
// "solver", the value and the allowed names otherwise.
SolverType parse_solver_type(std::string_view name);
// Every solver type, in the order --help lists them.
std::vector<SolverType> solver_types();
// Whether the solver works on the FFT operator (the Polonsky-Keer family),
// so that fft_planning and deflation concern it.
bool uses_fft(SolverType type);

// The arithmetic of the Polonsky-Keer solvers (docs/solvers.md, "Mixed
// precision").
enum class Precision {
  double_precision,  // every transform and field in double
  // The step's products K t and K c (periodic grids) and the Fourier
  // preconditioner through single-precision transforms; the displacement
  // K p refreshed in double (iterative refinement), the residual, the
  // contact decisions and the independent convergence check in double
  // (polonsky_keer.hpp, "Mixed precision"), so the requested tolerance is
  // met in double or the solve says it was not.
  mixed,
};

// "double", "mixed".
std::string_view to_string(Precision precision);
// The inverse of to_string(Precision); throws SolverOptionError naming the
// option "precision", the value and the allowed names otherwise.
Precision parse_precision(std::string_view name);

// A broken rule of SolverOptions: an OptionError whose option() is the
// option as SolverOptions spells it ("tolerance", "deflation.block", ...).
class SolverOptionError : public OptionError {
 public:
  using OptionError::OptionError;
};

// pk_multilevel's coarse-grid start.
struct MultilevelOptions {
  // Residual tolerance of the coarse solves: they only place the contact
  // edges for the next grid, so a loose tolerance suffices (the fine solve
  // uses the requested one).
  double coarse_tolerance = 1e-4;
  // No grid coarser than this many cells per axis is made.
  std::size_t min_cells_per_axis = 32;
  // A warm start under load control is used only while the target force is
  // within this factor of the start's force; further off, the coarse grids
  // give the better start (docs/solvers.md, warm starts).
  double warm_start_max_load_ratio = 1.5;
  // Whether the fine grid's solve begins with a primal-dual active-set
  // phase from the prolonged start (active_set_start.hpp); block deflation
  // then applies from DeflationOptions::kAutomaticWithActiveSetFromCells on,
  // unless turned off. on: on 2D grids without a hardness cap, on any
  // layout (serial or slabs); automatic: where active_set_applies says it
  // pays.
  enum class ActiveSet { off, on, automatic };
  ActiveSet active_set = ActiveSet::automatic;
  ActiveSetOptions active_set_options;

  // The automatic rule: the phase cuts the FFT pairs per solve from 1024^2
  // on, but each of its deflated iterations costs more than a pair, and the
  // time falls only from this many cells (rough periodic surfaces, 3 seeds:
  // 1024^2 and 2048^2 4 % more CPU time, 4096^2 7-15 % less, 8192^2 half the
  // iterations; docs/development-log.md, "the active-set phase made
  // automatic").
  static constexpr std::size_t kActiveSetAutomaticFromCells = std::size_t{1} << 24;
  // Whether the phase runs on the finest grid `grid` of a solve (on one
  // process or on slabs alike): on, or automatic on a periodic grid of at
  // least kActiveSetAutomaticFromCells cells and a homogeneous half-space
  // (`coated` false; free grids and coatings were not measured at that
  // size); never on 1D grids or with a hardness cap (`capped`).
  bool active_set_applies(const Grid& grid, bool capped, bool coated) const;

  // Throws SolverOptionError naming the option ("multilevel.coarse_tolerance",
  // ...) unless 0 < coarse_tolerance < 1, min_cells_per_axis >= 2,
  // warm_start_max_load_ratio >= 1 and active_set_options are valid.
  void validate() const;
};

// "on", "off", "automatic".
std::string_view to_string(MultilevelOptions::ActiveSet mode);
// The inverse of to_string(MultilevelOptions::ActiveSet); throws
// SolverOptionError naming the option "multilevel.active_set", the value and
// the allowed names otherwise.
MultilevelOptions::ActiveSet parse_active_set(std::string_view name);

// The coarse-grid correction by block deflation (block_deflation.hpp) of
// pk_fourier and of pk_multilevel's finest grid; the block size and the
// coarse solve's limits are BlockDeflationOptions'.
struct DeflationOptions : BlockDeflationOptions {
  // off: never; on: always (pk_fourier or pk_multilevel only, on a grid the
  // block covers); automatic: on pk_multilevel's finest grid where
  // automatic_applies says it pays, never with pk_fourier.
  enum class Mode { off, on, automatic };
  Mode mode = Mode::automatic;

  // The automatic rule: the correction's costs (two more products per
  // iteration, the kernel product, assembling and solving the coarse
  // matrix) outweigh the iterations it saves below this many cells
  // (docs/solvers.md, "Block deflation").
  static constexpr std::size_t kAutomaticFromCells = std::size_t{1} << 22;
  // Whether automatic mode deflates on `grid`: 2D, periodic or free, at
  // least kAutomaticFromCells cells, and `block` dividing it into at least
  // 3 blocks per axis (BlockDeflation::covers).
  bool automatic_applies(const Grid& grid) const;
  // With pk_multilevel's active-set phase the correction joins the phase's
  // linear solves on a fixed set and pays from this many cells; below, the
  // phase's solves are short enough without it (rough surfaces, 256^2 and
  // 512^2: 8 % fewer FFT pairs without it, 1024^2: 11 % more;
  // docs/development-log.md, "fewer FFT pairs per solve").
  static constexpr std::size_t kAutomaticWithActiveSetFromCells = std::size_t{1} << 20;
  // Whether automatic mode deflates the active-set phase and its finish on
  // `grid`: as automatic_applies, from kAutomaticWithActiveSetFromCells.
  bool automatic_applies_with_active_set(const Grid& grid) const;
};

std::string_view to_string(DeflationOptions::Mode mode);

struct SolverOptions {
  // The default was chosen by measurement (docs/solvers.md).
  SolverType type = SolverType::pk_multilevel;
  // Relative residual at which the solve stops (the stopping criterion of
  // polonsky_keer.hpp; dense_contact.hpp for lemke and lcpquad).
  double tolerance = 1e-10;
  // Iteration limit of the iterative solvers (pivots for lemke); unset:
  // kDefaultMaxIterations. lcpquad takes none (ALGLIB's interior-point
  // method stops at its own tolerance), so setting it there is refused.
  std::optional<int> max_iterations;
  static constexpr int kDefaultMaxIterations = 10000;
  // FFTW planning of the FFT solvers. measure costs its planning once per
  // grid size (FFTW's wisdom keeps it) and buys faster transforms on large
  // grids (docs/solvers.md).
  FftPlanning fft_planning = FftPlanning::measure;
  // The arithmetic of the Polonsky-Keer solvers; mixed is refused by the
  // dense solvers, the adhesive solver and solves on several processes.
  // The default was chosen by measurement (docs/performance.md, "Mixed
  // precision").
  Precision precision = Precision::double_precision;
  // Called once per iteration of the fine solve with (iteration, residual);
  // may be empty. It runs on the calling thread between iterations; its
  // IterationDecision::stop ends the solve with status `stopped`.
  ProgressCallback progress;

  // The interface law: a hardness cap 0 <= p <= H (every solver but lemke,
  // whose pivoting solves the plain LCP only).
  InterfaceLaw interface_law;

  MultilevelOptions multilevel;  // pk_multilevel only
  DeflationOptions deflation;    // pk_fourier and pk_multilevel only

  // Adhesion: when set, make_solver builds the adhesive solver
  // (adhesive_contact_solver.hpp) with this law instead of `type`, with its
  // own tolerance (its residual is another measure than Polonsky-Keer's),
  // and max_iterations, fft_planning and progress from here.
  struct Adhesion {
    AdhesionLaw law;
    double tolerance = 1e-6;
    // Preconditioned conjugate gradients (the default) or SPG
    // (AdhesiveSolverOptions::precondition).
    bool precondition = true;
  };
  std::optional<Adhesion> adhesion;

  int iteration_limit() const { return max_iterations.value_or(kDefaultMaxIterations); }
  // The tolerance of the solver make_solver builds: the adhesive solver's
  // own with adhesion, `tolerance` otherwise (progress displays use it).
  double solver_tolerance() const { return adhesion ? adhesion->tolerance : tolerance; }

  // Throws SolverOptionError naming the option unless: 0 < tolerance < 1;
  // max_iterations >= 1, and unset for lcpquad; the nested options are
  // valid; deflation is on only for pk_fourier or pk_multilevel; a hardness
  // is not asked of lemke (its range every solver checks when it is made:
  // ContactSolver); with adhesion, the law is valid
  // ("adhesion.work", "adhesion.range"), its tolerance in (0, 1) and
  // deflation not on; precision mixed only with the Polonsky-Keer solvers
  // and without adhesion.
  void validate() const;
  // validate(), and the rules that depend on the grid: deflation on needs a
  // grid its block covers.
  void validate(const Grid& grid) const;
  // validate(grid), and the rules of a coated half-space (layered_material.hpp):
  // not a dense solver ("type": lemke and lcpquad assemble the homogeneous
  // matrix). Every grid is supported, with adhesion too.
  void validate(const Grid& grid, const LayeredMaterial& coating) const;
};

}  // namespace halfspace::solvers
