// Polonsky-Keer on a slab-distributed 2D grid: the serial solver loop
// (polonsky_keer.cpp) unchanged, over the slab operator (periodic or free)
// and preconditioner, whose reductions go through the operator's
// communicator. A hardness cap is elementwise (the projection onto [0, H])
// apart from its load-restoring scale and fill, whose sums and searches are
// reductions over that communicator too.
#include "halfspace/mpi/distributed_solver.hpp"

#include <fmt/format.h>

#include <utility>
#include <variant>

#include "halfspace/mpi/distributed_multilevel.hpp"
#include "halfspace/mpi/slab_fft.hpp"
#include "halfspace/mpi/slab_fourier_operator.hpp"
#include "halfspace/mpi/slab_free_operator.hpp"
#include "halfspace/solvers/balancing_preconditioner.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::mpi {
namespace {

using solvers::SolverOptionError;
using solvers::SolverType;

// A grid's distributed operator and, if asked for, its Fourier
// preconditioner.
struct SlabOperator {
  std::unique_ptr<InfluenceOperator> op;
  std::unique_ptr<solvers::Preconditioner> fourier;  // null unless asked for
};

// The operator of the 2D `grid` over `comm`: periodic, the kernel on the
// grid's transform, which the preconditioner shares (Polonsky-Keer applies
// them one after the other); free, the padded convolution, the
// preconditioner on a transform of its own (the unpadded periodic symbol,
// as the serial solvers use on free grids) working in the operator's padded
// buffer, idle between products. Collective.
// A coated half-space takes its layered kernel in both (periodic grids
// only: check_coating).
SlabOperator make_slab_operator(const Grid& grid, const SlabElasticity& elasticity, bool fourier, FftPlanning planning,
                                const MpiCommunicator& comm) {
  SlabOperator made;
  if (grid.periodic()) {
    auto transform = std::make_shared<SlabRealFft>(grid.nx(), grid.ny(), comm, planning);
    made.op = std::make_unique<SlabFourierOperator>(grid, elasticity, transform);
    if (fourier) made.fourier = std::make_unique<SlabFourierPreconditioner>(grid, elasticity, transform);
  } else {
    const double e_star = std::get<double>(elasticity);
    auto op = std::make_unique<SlabFreeOperator>(grid, e_star, comm, planning);
    if (fourier) {
      made.fourier = std::make_unique<SlabFourierPreconditioner>(
          grid, e_star, std::make_shared<SlabRealFft>(grid.nx(), grid.ny(), comm, planning, op->scratch()));
    }
    made.op = std::move(op);
  }
  return made;
}

// The solver with the operator and preconditioner it references.
class DistributedSolver final : public solvers::ContactSolver {
 public:
  // With `deflation`, the block-deflation coarse correction around the
  // Fourier preconditioner (which the slab must then have).
  DistributedSolver(SlabOperator slab, std::unique_ptr<solvers::BlockDeflation> deflation,
                    const solvers::PolonskyKeerOptions& options)
      : op_(std::move(slab.op)),
        fourier_(std::move(slab.fourier)),
        deflation_(std::move(deflation)),
        balancing_(deflation_ ? std::make_unique<solvers::BalancingPreconditioner>(*op_, *fourier_, *deflation_)
                              : nullptr),
        solver_(*op_, options, balancing_ ? static_cast<solvers::Preconditioner*>(balancing_.get()) : fourier_.get()) {}

  std::string_view name() const override { return solver_.name(); }
  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure) override {
    return solver_.solve(initial_gap, loading, initial_pressure);
  }
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) override {
    return solver_.solve_from(initial_gap, loading, std::move(start));
  }

 private:
  std::unique_ptr<InfluenceOperator> op_;
  std::unique_ptr<solvers::Preconditioner> fourier_;
  std::unique_ptr<solvers::BlockDeflation> deflation_;
  std::unique_ptr<solvers::BalancingPreconditioner> balancing_;  // around fourier_ and deflation_
  solvers::PolonskyKeer solver_;
};

constexpr const char* kNotYet = "is not available with more than one process yet";

}  // namespace

bool distributable(const Grid& grid, const solvers::SolverOptions& options) {
  try {
    check_distributable(grid, options);
  } catch (const SolverOptionError&) {
    return false;
  }
  return true;
}

void check_distributable(const Grid& grid, const solvers::SolverOptions& options) {
  if (grid.dimension() != 2) {
    throw SolverOptionError(
        "grid", fmt::format("{} ({}D, {})", grid.shape_string(), grid.dimension(), to_string(grid.boundary())),
        fmt::format("{}: only 2D grids are distributed", kNotYet));
  }
  if (options.adhesion && !grid.periodic()) {
    // The adhesive solver's displacement lives on the zero-padded grid,
    // whose padding rows the slab transforms never hold (slab_padded_fft.hpp).
    throw SolverOptionError("adhesion", std::string(to_string(options.adhesion->law.type)),
                            fmt::format("{} on a free grid: solve free adhesive contacts on one process (periodic "
                                        "ones are distributed)",
                                        kNotYet));
  }
  if (options.type != SolverType::pk && options.type != SolverType::pk_fourier &&
      options.type != SolverType::pk_multilevel) {
    throw SolverOptionError("type", std::string(to_string(options.type)),
                            fmt::format("{}: use solver pk-multilevel, pk-fourier or pk", kNotYet));
  }
}

void check_distributable(const Grid& grid, const LayeredMaterial& /*coating*/) {
  if (!grid.periodic()) {
    throw SolverOptionError("boundary", std::string(to_string(grid.boundary())),
                            fmt::format("with a coated half-space {}: solve coated free grids on one process "
                                        "(coated periodic grids are distributed)",
                                        kNotYet));
  }
}

std::unique_ptr<solvers::ContactSolver> make_distributed_solver(const Grid& grid, const SlabElasticity& elasticity,
                                                                const solvers::SolverOptions& options,
                                                                const MpiCommunicator& comm) {
  if (const auto* coating = std::get_if<LayeredMaterial>(&elasticity)) {
    options.validate(grid, validated(*coating));
    check_distributable(grid, *coating);
  } else {
    options.validate(grid);
  }
  check_distributable(grid, options);
  if (options.adhesion) {
    // The adhesive solver on the periodic slab operator, as make_solver
    // builds it on the serial one.
    auto transform = std::make_shared<SlabRealFft>(grid.nx(), grid.ny(), comm, options.fft_planning);
    return std::make_unique<solvers::AdhesiveContactSolver>(
        std::make_unique<SlabFourierOperator>(grid, elasticity, transform), solvers::contact_modulus(elasticity),
        solvers::adhesive_solver_options(options));
  }
  if (options.type == SolverType::pk_multilevel) return make_distributed_multilevel(grid, elasticity, options, comm);
  const bool projected = options.type == SolverType::pk_fourier;
  SlabOperator slab = make_slab_operator(grid, elasticity, projected, options.fft_planning, comm);
  // Block deflation as the serial pk-fourier takes it: when asked for (its
  // options were checked by validate), on the rows the operator holds.
  std::unique_ptr<solvers::BlockDeflation> deflation;
  if (projected && options.deflation.mode == solvers::DeflationOptions::Mode::on) {
    const SlabLayout layout = slab_layout(grid.nx(), grid.ny(), comm);
    deflation = std::make_unique<solvers::BlockDeflation>(grid, options.deflation, layout.first_row, layout.rows, comm);
  }
  return std::make_unique<DistributedSolver>(std::move(slab), std::move(deflation),
                                             solvers::polonsky_keer_options(options, options.tolerance, projected));
}

}  // namespace halfspace::mpi
