// Polonsky-Keer in its variants (plain, plain with the projected-gradient
// search set, Fourier-preconditioned, and Fourier-preconditioned from
// coarse-grid solutions), so every validation test runs on each;
// parameterised tests take a PkVariant.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/multilevel_solver.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::testing {

enum class PkVariant { plain, plain_projected, fourier, multilevel };

inline std::string variant_name(const ::testing::TestParamInfo<PkVariant>& info) {
  switch (info.param) {
    case PkVariant::plain:
      return "Plain";
    case PkVariant::plain_projected:
      return "PlainProjected";
    case PkVariant::fourier:
      return "FourierPreconditioned";
    case PkVariant::multilevel:
      return "Multilevel";
  }
  return "Unknown";
}

inline auto all_pk_variants() {
  return ::testing::Values(PkVariant::plain, PkVariant::plain_projected, PkVariant::fourier, PkVariant::multilevel);
}

// Polonsky-Keer on an operator it may own, with the preconditioner it owns.
class OwningPk final : public ContactSolver {
 public:
  OwningPk(std::unique_ptr<InfluenceOperator> owned, InfluenceOperator& op, double e_star, bool preconditioned,
           solvers::PolonskyKeerOptions options)
      : owned_(std::move(owned)),
        preconditioner_(preconditioned ? std::make_unique<solvers::FourierPreconditioner>(op.grid(), e_star) : nullptr),
        solver_(op, std::move(options), preconditioner_.get()) {}

  std::string_view name() const override { return solver_.name(); }
  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure = {}) override {
    return solver_.solve(initial_gap, loading, initial_pressure);
  }
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd&& start) override {
    return solver_.solve_from(initial_gap, loading, std::move(start));
  }

 private:
  std::unique_ptr<InfluenceOperator> owned_;
  std::unique_ptr<solvers::FourierPreconditioner> preconditioner_;
  solvers::PolonskyKeer solver_;
};

// The solver of `variant` on `op` (the multilevel variant's fine level; its
// coarse levels get FFT operators of their own).
class PkSolver {
 public:
  PkSolver(InfluenceOperator& op, double e_star, PkVariant variant, solvers::PolonskyKeerOptions options = {}) {
    // The restart rules and search sets of the factory's "pk", "pk-fourier" and "pk-multilevel".
    if (variant == PkVariant::plain || variant == PkVariant::plain_projected) {
      if (variant == PkVariant::plain_projected) options.search_set = solvers::SearchSet::contact_and_overlap;
      solver_ = std::make_unique<OwningPk>(nullptr, op, e_star, false, std::move(options));
      return;
    }
    options.restart = solvers::ConjugacyRestart::powell;
    options.search_set = solvers::SearchSet::contact_and_overlap;
    if (variant == PkVariant::fourier) {
      solver_ = std::make_unique<OwningPk>(nullptr, op, e_star, true, std::move(options));
      return;
    }
    auto make_level = [&op, e_star, options](const Grid& level, double tolerance,
                                             bool fine) -> std::unique_ptr<ContactSolver> {
      solvers::PolonskyKeerOptions level_options = options;
      level_options.tolerance = tolerance;
      if (fine) return std::make_unique<OwningPk>(nullptr, op, e_star, true, level_options);
      auto coarse_op = std::make_unique<FftInfluenceOperator>(level, e_star);
      InfluenceOperator& coarse = *coarse_op;
      return std::make_unique<OwningPk>(std::move(coarse_op), coarse, e_star, true, level_options);
    };
    solver_ = std::make_unique<solvers::MultilevelSolver>(op.grid(), options.tolerance, make_level);
  }

  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure = {}) {
    return solver_->solve(initial_gap, loading, initial_pressure);
  }
  SolveResult solve_from(std::span<const double> initial_gap, const Loading& loading, Eigen::ArrayXd start) {
    return solver_->solve_from(initial_gap, loading, std::move(start));
  }

 private:
  std::unique_ptr<ContactSolver> solver_;
};

}  // namespace halfspace::testing
