// Reproduction of Table 1 of the seed paper: each test solved by Lemke
// pivoting, the paper's LCPquad and Polonsky-Keer on the FFT operator, all on
// the same plane-strain strip kernel, under the same load, with the measures
// the summary table reports.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "halfspace/paper/table1.hpp"
#include "halfspace/solvers/lcp.hpp"
#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::paper {

struct ReproductionOptions {
  double load = kDefaultLoad;        // N/m
  double pk_tolerance = 1e-12;       // Polonsky-Keer residual tolerance
  double lcpquad_tolerance = 1e-12;  // ALGLIB dense-IPM tolerance (Hertz units)
  double dense_tolerance = 1e-10;    // contact residual at which Lemke and LCPquad count as converged
  // Also solve LCPquad without nondimensionalisation, in SI units: with the
  // load as an equality, and under the approach Lemke found (the paper's
  // displacement control).
  bool unscaled_qp = false;
  // Also solve with the paper's eq. (4) kernel (point_load_matrix) by Lemke.
  bool point_load_kernel = false;

  // Throws InputError naming the option unless every value is valid.
  void validate() const;
};

// One method's pressure where it is not one of the three main ones.
struct ExtraPressure {
  std::string column;        // e.g. "p_lcpquad_si"
  std::string description;   // one line
  Eigen::ArrayXd pressure;   // Pa as the method returned it
  solvers::LcpSolution lcp;  // the method's report
};

struct TestReproduction {
  LineContact contact;
  SolveResult lemke;
  SolveResult lcpquad;
  SolveResult pk;
  solvers::LcpSolution lemke_report;    // pivots, ray termination
  solvers::LcpSolution lcpquad_report;  // QP objective, IPM iterations
  Eigen::ArrayXd hertz_pressure;        // at the nodes (Pa)
  std::vector<ExtraPressure> extras;    // from unscaled_qp, point_load_kernel

  // Largest pressure difference between two methods, over the Hertz maximum.
  double lemke_vs_lcpquad = 0.0;
  double lemke_vs_pk = 0.0;
  double lcpquad_vs_pk = 0.0;

  bool all_converged() const { return lemke.converged() && lcpquad.converged() && pk.converged(); }
};

// Number of nodes with p > 0, and the contact half-width they cover (m):
// half the total width of the cells in contact.
int contact_nodes(const SolveResult& result);
double contact_half_width(const SolveResult& result, double dx);

// Runs test `test` with every method. Throws InputError for invalid options;
// non-convergence is in the results' status.
TestReproduction reproduce(const PaperTest& test, const ReproductionOptions& options);

}  // namespace halfspace::paper
