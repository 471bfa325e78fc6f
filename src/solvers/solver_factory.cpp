// Solver construction by name. Each solver is stored with the operator it
// references, so the pair lives and dies together.
#include "halfspace/solvers/solver_factory.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/lcp_quad.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "halfspace/solvers/multilevel_solver.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::solvers {
namespace {

// A solver together with the operator (and preconditioner) it was built on.
class SolverWithOperator final : public ContactSolver {
 public:
  SolverWithOperator(std::unique_ptr<InfluenceOperator> op, std::unique_ptr<Preconditioner> preconditioner,
                     std::unique_ptr<BlockDeflation> deflation, std::unique_ptr<ContactSolver> solver)
      : op_(std::move(op)),
        preconditioner_(std::move(preconditioner)),
        deflation_(std::move(deflation)),
        solver_(std::move(solver)) {}

  std::string_view name() const override { return solver_->name(); }
  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure) override {
    return solver_->solve(initial_gap, loading, initial_pressure);
  }
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) override {
    return solver_->solve_from(initial_gap, loading, std::move(start));
  }

 private:
  std::unique_ptr<InfluenceOperator> op_;
  std::unique_ptr<Preconditioner> preconditioner_;
  std::unique_ptr<BlockDeflation> deflation_;
  std::unique_ptr<ContactSolver> solver_;
};

std::unique_ptr<ContactSolver> make_polonsky_keer(const Grid& grid, double e_star, const SolverSettings& settings,
                                                  bool preconditioned, ConjugacyRestart restart, bool deflated) {
  PolonskyKeerOptions options;
  options.tolerance = settings.tolerance;
  options.max_iterations = settings.max_iterations;
  options.progress = settings.progress;
  options.restart = restart;
  // The paper's search set for plain Polonsky-Keer; the projected-gradient
  // one with the preconditioner, where it saves 6-13 % of the iterations up to
  // 2048^2 and 30-45 % at 4096^2-8192^2 (docs/performance.md).
  options.search_set = preconditioned ? SearchSet::contact_and_overlap : SearchSet::contact;
  // Not on 1D grids: there the preconditioned steps clip hundreds of cells
  // each, and the iteration cycles on measured profiles under moderate loads
  // (dektak-1 at 1e5-1e6 Pa, residual stuck at 2-6e-2), while the
  // projected-gradient search set alone converges at every load
  // (docs/validation.md, "Measured profiles").
  preconditioned = preconditioned && grid.dimension() == 2;
  std::unique_ptr<FftInfluenceOperator> op;
  std::unique_ptr<Preconditioner> preconditioner;
  if (preconditioned && grid.periodic()) {
    // Both transform the unpadded grid, and Polonsky-Keer applies them one
    // after the other: one transform serves both, which saves a real and a
    // complex array per cell (docs/performance.md).
    auto transform = make_grid_transform(grid, settings.fft_planning);
    op = std::make_unique<FftInfluenceOperator>(grid, e_star, transform);
    preconditioner = std::make_unique<FourierPreconditioner>(grid, e_star, transform);
  } else {
    // Free grids: the preconditioner's unpadded transform works in the
    // operator's padded buffer, idle between products (16 B per cell less).
    op = std::make_unique<FftInfluenceOperator>(grid, e_star, settings.fft_planning);
    if (preconditioned) {
      preconditioner = std::make_unique<FourierPreconditioner>(
          grid, e_star, make_grid_transform(grid, settings.fft_planning, op->scratch()));
    }
  }
  std::unique_ptr<BlockDeflation> deflation;
  if (deflated) {
    BlockDeflationOptions deflation_options;
    deflation_options.block = settings.deflation_block.value_or(kDefaultDeflationBlock);
    deflation = std::make_unique<BlockDeflation>(grid, deflation_options);
  }
  auto solver = std::make_unique<PolonskyKeer>(*op, options, preconditioner.get(), deflation.get());
  return std::make_unique<SolverWithOperator>(std::move(op), std::move(preconditioner), std::move(deflation),
                                              std::move(solver));
}

// Whether pk-multilevel's fine grid gets the coarse correction: as asked,
// or by default.
bool deflated(const Grid& grid, const SolverSettings& settings) {
  if (settings.deflation_block) return *settings.deflation_block > 0;
  return default_deflation(grid);
}

// Fourier-preconditioned Polonsky-Keer with Powell restarts on every level.
std::unique_ptr<ContactSolver> make_multilevel(const Grid& grid, double e_star, const SolverSettings& settings) {
  auto make_level = [e_star, settings](const Grid& level, double tolerance, bool fine) {
    SolverSettings level_settings = settings;
    level_settings.tolerance = tolerance;
    if (!fine) level_settings.progress = {};  // progress reports the fine solve only
    // The coarse-grid correction on the finest grid only, where the
    // contact has the most spots.
    return make_polonsky_keer(level, e_star, level_settings, true, ConjugacyRestart::powell,
                              fine && deflated(level, settings));
  };
  return std::make_unique<MultilevelSolver>(grid, settings.tolerance, make_level);
}

// The dense LCP solvers own their assembled matrix; they refuse grids over
// kMaxDenseCells with a message that points to "pk".
std::unique_ptr<ContactSolver> make_dense(const Grid& grid, double e_star, const SolverSettings& settings) {
  DenseContactOptions contact;
  contact.tolerance = settings.tolerance;
  if (settings.name == "lemke")
    return std::make_unique<Lemke>(grid, e_star, LemkeOptions{settings.max_iterations}, contact);
  return std::make_unique<LcpQuad>(grid, e_star, LcpQuadOptions{}, contact);
}

}  // namespace

bool default_deflation(const Grid& grid) {
  return grid.size() >= kDefaultDeflationFromCells && BlockDeflation::covers(grid, kDefaultDeflationBlock);
}

std::vector<std::string> solver_names() {
  return {"pk-multilevel", "pk-fourier", "pk", "lemke", "lcpquad"};
}

std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverSettings& settings) {
  // Plain Polonsky-Keer keeps the paper's restart rule; with the Fourier
  // preconditioner Powell's restart test cuts the iterations (docs/performance.md).
  if (settings.deflation_block.value_or(0) > 0 && settings.name != "pk-fourier" && settings.name != "pk-multilevel") {
    throw InputError(fmt::format(
        "solver '{}' has no coarse-grid correction: deflation needs pk-fourier or pk-multilevel", settings.name));
  }
  if (settings.name == "pk") {
    return make_polonsky_keer(grid, e_star, settings, false, ConjugacyRestart::on_entry, false);
  }
  if (settings.name == "pk-fourier") {
    return make_polonsky_keer(grid, e_star, settings, true, ConjugacyRestart::powell,
                              settings.deflation_block.value_or(0) > 0);
  }
  if (settings.name == "pk-multilevel") return make_multilevel(grid, e_star, settings);
  if (settings.name == "lemke" || settings.name == "lcpquad") return make_dense(grid, e_star, settings);
  throw InputError(
      fmt::format("solver '{}' is not known: use one of {}", settings.name, fmt::join(solver_names(), ", ")));
}

}  // namespace halfspace::solvers
