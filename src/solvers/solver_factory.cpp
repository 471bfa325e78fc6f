// Solver construction from SolverOptions. Each solver is stored with the operator it
// references, so the pair lives and dies together.
#include "halfspace/solvers/solver_factory.hpp"

#include <fmt/format.h>

#include <memory>
#include <variant>

#include "halfspace/error.hpp"
#include "halfspace/fft/grid_transform.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/active_set_start.hpp"
#include "halfspace/solvers/adhesive_contact_solver.hpp"
#include "halfspace/solvers/balancing_preconditioner.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/lcp_quad.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "halfspace/solvers/multilevel_solver.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::solvers {
namespace {

// A solver together with the operator and preconditioners it was built on.
class SolverWithOperator final : public ContactSolver {
 public:
  SolverWithOperator(std::unique_ptr<InfluenceOperator> op, std::unique_ptr<Preconditioner> fourier,
                     std::unique_ptr<BlockDeflation> deflation, std::unique_ptr<Preconditioner> balancing,
                     std::unique_ptr<ContactSolver> solver)
      : op_(std::move(op)),
        fourier_(std::move(fourier)),
        deflation_(std::move(deflation)),
        balancing_(std::move(balancing)),
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
  std::unique_ptr<Preconditioner> fourier_;
  std::unique_ptr<BlockDeflation> deflation_;
  std::unique_ptr<Preconditioner> balancing_;  // around fourier_ and deflation_
  std::unique_ptr<ContactSolver> solver_;
};

// The half-space: homogeneous with composite modulus E* (Pa), or coated. The
// operator and the Fourier preconditioner take the same one, so the
// preconditioner inverts the kernel in use, on every multilevel level.
using Elasticity = std::variant<double, LayeredMaterial>;

template <class Transform>
std::unique_ptr<FftInfluenceOperator> make_operator(const Grid& grid, const Elasticity& elasticity,
                                                    Transform&& transform) {
  return std::visit(
      [&](const auto& material) {
        return std::make_unique<FftInfluenceOperator>(grid, material, std::forward<Transform>(transform));
      },
      elasticity);
}

std::unique_ptr<Preconditioner> make_fourier(const Grid& grid, const Elasticity& elasticity,
                                             std::shared_ptr<RealFft> transform) {
  return std::visit(
      [&](const auto& material) -> std::unique_ptr<Preconditioner> {
        return std::make_unique<FourierPreconditioner>(grid, material, std::move(transform));
      },
      elasticity);
}

// Nor on free grids under a layer much stiffer than its substrate: the
// layer spreads a load over a bending length that grows like
// t (E1*/E2*)^(1/3) (LayeredKernel::split_height), a compliance the
// symbol sampled on the unpadded grid misses; the projected steps then
// stalled (a sphere on a 20 um layer, E1*/E2* = 2e4: 2700 preconditioned
// iterations against 2600 without, 1e5 and above: no convergence in
// 10,000; the projected form without it stalled from 1e5 too, while the
// paper's form converged in 2600 and 3800 at 2e4 and 1e5; issue 32). Up to
// 1e4 the preconditioner still saves iterations (760 against 1040 at 1e4).
// Beyond, every Polonsky-Keer type solves in the paper's form.
constexpr double kMaxPreconditionedCoatingRatio = 1e4;

bool stiff_coating_on_free_grid(const Grid& grid, const Elasticity& elasticity) {
  const auto* material = std::get_if<LayeredMaterial>(&elasticity);
  return material && !grid.periodic() &&
         plane_strain_modulus(material->layer) >
             kMaxPreconditionedCoatingRatio * plane_strain_modulus(material->substrate);
}

// Polonsky-Keer on an FFT operator: the paper's form, or the projected
// form with the Fourier preconditioner (and the coarse correction if
// `deflated`) when `projected`; begun by the primal-dual active-set phase
// if `active_set` and the preconditioner applies.
std::unique_ptr<ContactSolver> make_polonsky_keer(const Grid& grid, const Elasticity& e_star,
                                                  const SolverOptions& options, double tolerance, bool fine,
                                                  bool projected, bool deflated, bool active_set = false) {
  // A stiff layer on a soft substrate on a free grid: the paper's form
  // (see stiff_coating_on_free_grid).
  if (stiff_coating_on_free_grid(grid, e_star)) projected = false;
  PolonskyKeerOptions pk = polonsky_keer_options(options, tolerance, projected);
  if (!fine) pk.progress = nullptr;  // progress reports the fine solve only
  // The preconditioner not on 1D grids: there the preconditioned steps clip
  // hundreds of cells each, and the iteration cycles on measured profiles
  // under moderate loads, while the projected form alone converges at every
  // load (docs/validation.md, "Measured profiles").
  const bool preconditioned = projected && grid.dimension() == 2;
  std::unique_ptr<FftInfluenceOperator> op;
  std::unique_ptr<Preconditioner> preconditioner;
  if (preconditioned && grid.periodic()) {
    // Both transform the unpadded grid, and Polonsky-Keer applies them one
    // after the other: one transform serves both, which saves a real and a
    // complex array per cell.
    auto transform = make_grid_transform(grid, options.fft_planning);
    op = make_operator(grid, e_star, transform);
    preconditioner = make_fourier(grid, e_star, transform);
  } else {
    // Free grids: the preconditioner's unpadded transform works in the
    // operator's padded buffer, idle between products (16 B per cell less).
    op = make_operator(grid, e_star, options.fft_planning);
    if (preconditioned) {
      preconditioner = make_fourier(grid, e_star, make_grid_transform(grid, options.fft_planning, op->scratch()));
    }
  }
  std::unique_ptr<BlockDeflation> deflation;
  std::unique_ptr<Preconditioner> balancing;
  if (deflated && preconditioner) {
    deflation = std::make_unique<BlockDeflation>(grid, options.deflation);
    balancing = std::make_unique<BalancingPreconditioner>(*op, *preconditioner, *deflation);
  }
  Preconditioner* used = balancing ? balancing.get() : preconditioner.get();
  auto polonsky_keer = std::make_unique<PolonskyKeer>(*op, pk, used);
  std::unique_ptr<ContactSolver> solver;
  if (active_set && used && !options.interface_law.hardness) {
    solver =
        std::make_unique<ActiveSetStart>(*op, *used, std::move(polonsky_keer), options.multilevel.active_set_options);
  } else {
    solver = std::move(polonsky_keer);
  }
  return std::make_unique<SolverWithOperator>(std::move(op), std::move(preconditioner), std::move(deflation),
                                              std::move(balancing), std::move(solver));
}

// Fourier-preconditioned Polonsky-Keer on every level; the coarse-grid
// correction on the finest grid only, where the contact has the most spots.
std::unique_ptr<ContactSolver> make_multilevel(const Grid& grid, const Elasticity& e_star,
                                               const SolverOptions& options) {
  // With the active-set phase, block deflation (unless turned off) wherever
  // its block covers the grid: the phase's linear solves on a fixed set
  // need no settling before the correction joins.
  const bool active_set = options.multilevel.active_set && !options.interface_law.hardness;
  const bool deflated = multilevel_deflates(grid, options) ||
                        (active_set && options.deflation.mode == DeflationOptions::Mode::automatic &&
                         BlockDeflation::covers(grid, options.deflation.block));
  auto make_level = [e_star, options, deflated, active_set](const Grid& level, double tolerance, bool fine) {
    return make_polonsky_keer(level, e_star, options, tolerance, fine, true, fine && deflated, fine && active_set);
  };
  return std::make_unique<MultilevelSolver>(grid, options.tolerance, make_level, options.multilevel);
}

// The dense LCP solvers own their assembled matrix; they refuse grids over
// kMaxDenseCells with a message that points to "pk".
std::unique_ptr<ContactSolver> make_dense(const Grid& grid, double e_star, const SolverOptions& options) {
  DenseContactOptions contact;
  contact.tolerance = options.tolerance;
  contact.hardness = options.interface_law.hardness;
  if (options.type == SolverType::lemke) {
    return std::make_unique<Lemke>(grid, e_star, LemkeOptions{options.iteration_limit()}, contact);
  }
  return std::make_unique<LcpQuad>(grid, e_star, LcpQuadOptions{}, contact);
}

std::unique_ptr<ContactSolver> make_any_solver(const Grid& grid, const Elasticity& e_star,
                                               const SolverOptions& options) {
  options.validate(grid);
  if (options.adhesion) {
    return std::make_unique<AdhesiveContactSolver>(make_operator(grid, e_star, options.fft_planning),
                                                   contact_modulus(e_star), adhesive_solver_options(options));
  }
  switch (options.type) {
    case SolverType::pk:
      return make_polonsky_keer(grid, e_star, options, options.tolerance, true, false, false);
    case SolverType::pk_fourier:
      return make_polonsky_keer(grid, e_star, options, options.tolerance, true, true,
                                options.deflation.mode == DeflationOptions::Mode::on);
    case SolverType::pk_multilevel:
      return make_multilevel(grid, e_star, options);
    case SolverType::lemke:
    case SolverType::lcpquad:
      return make_dense(grid, std::get<double>(e_star), options);
  }
  throw InputError(fmt::format("solver type {} is not known", static_cast<int>(options.type)));
}

}  // namespace

PolonskyKeerOptions polonsky_keer_options(const SolverOptions& options, double tolerance, bool projected) {
  PolonskyKeerOptions pk;
  pk.tolerance = tolerance;
  pk.max_iterations = options.iteration_limit();
  pk.progress = options.progress;
  pk.form = projected ? PolonskyKeerForm::projected : PolonskyKeerForm::paper;
  pk.bounds = options.interface_law.bounds();
  return pk;
}

AdhesiveSolverOptions adhesive_solver_options(const SolverOptions& options) {
  AdhesiveSolverOptions adhesive;
  adhesive.law = options.adhesion.value().law;
  adhesive.tolerance = options.adhesion->tolerance;
  adhesive.precondition = options.adhesion->precondition;
  adhesive.hardness = options.interface_law.hardness;
  if (options.max_iterations) adhesive.max_iterations = *options.max_iterations;
  adhesive.fft_planning = options.fft_planning;
  adhesive.progress = options.progress;
  return adhesive;
}

double contact_modulus(const std::variant<double, LayeredMaterial>& elasticity) {
  if (const auto* coating = std::get_if<LayeredMaterial>(&elasticity)) return plane_strain_modulus(coating->layer);
  return std::get<double>(elasticity);
}

bool multilevel_deflates(const Grid& grid, const SolverOptions& options) {
  using Mode = DeflationOptions::Mode;
  // Not by default with a hardness cap: its steps keep clipping cells at the
  // cap, so the schedule never found them settled and the correction never
  // joined in the capped solves measured (docs/theory.md#hardness-cap); it would cost
  // its memory for nothing. Asked for (Mode::on), it applies.
  return options.deflation.mode == Mode::on ||
         (options.deflation.mode == Mode::automatic && options.deflation.automatic_applies(grid) &&
          !options.interface_law.hardness);
}

std::unique_ptr<ContactSolver> make_solver(const Grid& grid, double e_star, const SolverOptions& options) {
  return make_any_solver(grid, Elasticity{e_star}, options);
}

std::unique_ptr<ContactSolver> make_solver(const Grid& grid, const LayeredMaterial& material,
                                           const SolverOptions& options) {
  validated(material);
  options.validate(grid, material);
  return make_any_solver(grid, Elasticity{material}, options);
}

}  // namespace halfspace::solvers
