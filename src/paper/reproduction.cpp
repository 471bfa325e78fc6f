// Runs one Table 1 test with Lemke, LCPquad and Polonsky-Keer, and the
// optional demonstrations of docs/paper.md (the QP in SI units, eq. (4)).
// The dense solvers work in Hertz units: lengths in b, pressures in p_H.
#include "halfspace/paper/reproduction.hpp"

#include <fmt/format.h>

#include <cmath>
#include <span>

#include "halfspace/error.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/lcp_quad.hpp"
#include "halfspace/solvers/lemke.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::paper {
namespace {

double max_difference(const Eigen::ArrayXd& a, const Eigen::ArrayXd& b, double scale) {
  return (a - b).abs().maxCoeff() / scale;
}

// LCPquad on the SI problem, as the paper poses it: no scaling at all. The
// pressure is the QP's raw solution, without the contact identification of
// the dense solvers (which compares pressures with gaps, meaningless in SI).
ExtraPressure unscaled_lcpquad(const LineContact& contact, const Loading& loading, const ReproductionOptions& options,
                               std::string column, std::string description) {
  solvers::DenseContactOptions si;
  si.nondimensionalise = false;
  si.tolerance = options.dense_tolerance;
  solvers::LcpQuad solver(contact.grid, contact.e_star, solvers::LcpQuadOptions{options.lcpquad_tolerance}, si);
  const std::span<const double> gap(contact.initial_gap.data(), contact.x.size());
  solver.solve(gap, loading);
  return {std::move(column), std::move(description), solver.last_solution().z.array(), solver.last_solution()};
}

// Lemke with the paper's eq. (4) matrix. It is m/N, so no length unit makes
// it dimensionless; it is scaled by its diagonal instead (length unit
// K_ii E*, which makes M_ii = 1).
ExtraPressure point_load_lemke(const LineContact& contact, const ReproductionOptions& options) {
  Eigen::MatrixXd matrix = point_load_matrix(contact);
  solvers::DenseContactOptions scaled;
  scaled.units.length = matrix(0, 0) * contact.e_star;
  scaled.tolerance = options.dense_tolerance;
  solvers::Lemke solver(contact.grid, contact.e_star, std::move(matrix), {}, scaled);
  const std::span<const double> gap(contact.initial_gap.data(), contact.x.size());
  const SolveResult result = solver.solve(gap, Loading::force(contact.load));
  return {"p_lemke_eq4", "Lemke with the paper's eq. (4) point-load kernel (m/N), diagonal 4 ln(1+sqrt2)/dx",
          result.pressure, solver.last_solution()};
}

}  // namespace

void ReproductionOptions::validate() const {
  if (!(std::isfinite(load) && load > 0.0)) {
    throw InputError(fmt::format("load = {} N/m is invalid: must be positive and finite", format_number(load)));
  }
  if (!(pk_tolerance > 0.0 && pk_tolerance < 1.0)) {
    throw InputError(
        fmt::format("Polonsky-Keer tolerance = {} is invalid: allowed range is (0, 1)", format_number(pk_tolerance)));
  }
  solvers::LcpQuadOptions{lcpquad_tolerance}.validate();
  if (!(dense_tolerance > 0.0 && dense_tolerance < 1.0)) {
    throw InputError(
        fmt::format("dense tolerance = {} is invalid: allowed range is (0, 1)", format_number(dense_tolerance)));
  }
}

int contact_nodes(const SolveResult& result) {
  return static_cast<int>((result.pressure > 0.0).count());
}

double contact_half_width(const SolveResult& result, double dx) {
  return 0.5 * dx * static_cast<double>(contact_nodes(result));
}

TestReproduction reproduce(const PaperTest& test, const ReproductionOptions& options) {
  options.validate();
  TestReproduction run{line_contact(test, options.load), {}, {}, {}, {}, {}, {}, {}};
  const LineContact& contact = run.contact;
  const std::span<const double> gap(contact.initial_gap.data(), contact.x.size());
  const Loading loading = Loading::force(contact.load);

  solvers::DenseContactOptions hertz_units;
  hertz_units.units = {contact.hertz.half_width, contact.hertz.peak};
  hertz_units.tolerance = options.dense_tolerance;

  solvers::Lemke lemke(contact.grid, contact.e_star, {}, hertz_units);
  run.lemke = lemke.solve(gap, loading);
  run.lemke_report = lemke.last_solution();

  solvers::LcpQuad lcpquad(contact.grid, contact.e_star, solvers::LcpQuadOptions{options.lcpquad_tolerance},
                           hertz_units);
  run.lcpquad = lcpquad.solve(gap, loading);
  run.lcpquad_report = lcpquad.last_solution();

  FftInfluenceOperator op(contact.grid, contact.e_star);
  solvers::PolonskyKeerOptions pk_options;
  pk_options.tolerance = options.pk_tolerance;
  solvers::PolonskyKeer pk(op, pk_options);
  run.pk = pk.solve(gap, loading);

  run.hertz_pressure.resize(static_cast<Eigen::Index>(contact.x.size()));
  for (std::size_t i = 0; i < contact.x.size(); ++i) {
    run.hertz_pressure[static_cast<Eigen::Index>(i)] = contact.hertz.pressure(contact.x[i]);
  }
  const double peak = contact.hertz.peak;
  run.lemke_vs_lcpquad = max_difference(run.lemke.pressure, run.lcpquad.pressure, peak);
  run.lemke_vs_pk = max_difference(run.lemke.pressure, run.pk.pressure, peak);
  run.lcpquad_vs_pk = max_difference(run.lcpquad.pressure, run.pk.pressure, peak);

  if (options.unscaled_qp) {
    run.extras.push_back(unscaled_lcpquad(contact, loading, options, "p_lcpquad_si",
                                          "LCPquad in SI units, load as an equality (no nondimensionalisation)"));
    run.extras.push_back(unscaled_lcpquad(contact, Loading::approach(run.lemke.approach), options,
                                          "p_lcpquad_si_approach",
                                          "LCPquad in SI units under the approach Lemke found (the paper's setting)"));
  }
  if (options.point_load_kernel) run.extras.push_back(point_load_lemke(contact, options));
  return run;
}

}  // namespace halfspace::paper
