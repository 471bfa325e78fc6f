// Polonsky-Keer in both variants (plain and Fourier-preconditioned), so every
// validation test runs on each; parameterised tests take a PkVariant.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/fourier_preconditioner.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::testing {

enum class PkVariant { plain, fourier };

inline std::string variant_name(const ::testing::TestParamInfo<PkVariant>& info) {
  return info.param == PkVariant::plain ? "Plain" : "FourierPreconditioned";
}

// The solver of `variant` on `op`, owning its preconditioner.
class PkSolver {
 public:
  PkSolver(InfluenceOperator& op, double e_star, PkVariant variant, solvers::PolonskyKeerOptions options = {})
      : preconditioner_(variant == PkVariant::fourier
                            ? std::make_unique<solvers::FourierPreconditioner>(op.grid(), e_star)
                            : nullptr),
        solver_(op, std::move(options), preconditioner_.get()) {}

  SolveResult solve(std::span<const double> initial_gap, const Loading& loading,
                    std::span<const double> initial_pressure = {}) {
    return solver_.solve(initial_gap, loading, initial_pressure);
  }

 private:
  std::unique_ptr<solvers::FourierPreconditioner> preconditioner_;
  solvers::PolonskyKeer solver_;
};

}  // namespace halfspace::testing
