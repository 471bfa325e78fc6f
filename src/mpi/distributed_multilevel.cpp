#include "halfspace/mpi/distributed_multilevel.hpp"

#include <utility>
#include <variant>

#include "halfspace/mpi/distributed_solver.hpp"
#include "halfspace/mpi/slab_level_transfer.hpp"
#include "halfspace/solvers/multilevel_solver.hpp"
#include "halfspace/solvers/solver_factory.hpp"

namespace halfspace::mpi {

std::unique_ptr<solvers::ContactSolver> make_distributed_multilevel(const Grid& grid, const SlabElasticity& elasticity,
                                                                    const solvers::SolverOptions& options,
                                                                    const MpiCommunicator& comm) {
  auto transfer = std::make_unique<SlabLevelTransfer>(grid, options.multilevel.min_cells_per_axis, comm);
  const SlabLevelTransfer* levels = transfer.get();  // owned by the solver, as is this factory
  // Each level is the Fourier-preconditioned Polonsky-Keer at the level's
  // tolerance, with the block deflation on the finest grid when the serial
  // pk-multilevel takes it there (solver_factory.cpp's rule).
  using Mode = solvers::DeflationOptions::Mode;
  const bool deflated = solvers::multilevel_deflates(grid, options);
  solvers::SolverOptions level_options = options;
  level_options.type = solvers::SolverType::pk_fourier;
  auto make_level = [elasticity, level_options, deflated, levels, &comm](const Grid& level, double tolerance,
                                                                         bool fine) {
    solvers::SolverOptions one = level_options;
    one.tolerance = tolerance;
    one.deflation.mode = fine && deflated ? Mode::on : Mode::off;
    if (!fine) one.progress = nullptr;  // progress reports the fine solve only
    if (!levels->gathered(level)) return make_distributed_solver(level, elasticity, one, comm);
    // Solved on every process alike: estimated plans, since measured ones
    // may differ between processes and so round differently.
    one.fft_planning = FftPlanning::estimate;
    return std::visit([&](const auto& material) { return solvers::make_solver(level, material, one); }, elasticity);
  };
  return std::make_unique<solvers::MultilevelSolver>(grid, options.tolerance, make_level, options.multilevel,
                                                     std::move(transfer));
}

}  // namespace halfspace::mpi
