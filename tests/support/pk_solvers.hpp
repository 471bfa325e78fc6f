// The Polonsky-Keer solvers of the public factory (pk, pk-fourier,
// pk-multilevel), so every validation test runs on each; parameterised
// tests take a SolverType.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::testing {

inline std::string solver_type_name(const ::testing::TestParamInfo<solvers::SolverType>& info) {
  switch (info.param) {
    case solvers::SolverType::pk:
      return "Plain";
    case solvers::SolverType::pk_fourier:
      return "FourierPreconditioned";
    case solvers::SolverType::pk_multilevel:
      return "Multilevel";
    default:
      return "Dense";
  }
}

inline auto all_pk_solvers() {
  return ::testing::Values(solvers::SolverType::pk, solvers::SolverType::pk_fourier,
                           solvers::SolverType::pk_multilevel);
}

// Options for `type` as a test wants them: the library's defaults but for
// FFT plans by estimate (measure would time candidate plans in every test,
// and its choice may differ between runs).
inline solvers::SolverOptions test_options(solvers::SolverType type, double tolerance = 1e-10) {
  solvers::SolverOptions options;
  options.type = type;
  options.tolerance = tolerance;
  options.fft_planning = FftPlanning::estimate;
  return options;
}

}  // namespace halfspace::testing
