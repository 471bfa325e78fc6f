// Using halfspace as a library: a random self-affine surface, a load sweep
// with warm starts, and the contact statistics of every step; the result is
// written as the `halfspace` program would write it. Build against the
// installed package with find_package(halfspace) and halfspace::halfspace.
//
//   library_usage [OUTPUT.h5]      (default: library_usage.h5)
#include <cstdio>
#include <exception>
#include <vector>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"

int main(int argc, char** argv) {
  using namespace halfspace;
  try {
    // 1. A periodic 256 x 256 grid of 0.5 um cells and a self-affine surface
    //    on it: H = 0.8, wavelengths from 8 cells to the domain, rms slope 0.1.
    const Grid grid = Grid::plane(256, 256, 0.5e-6, 0.5e-6, Boundary::periodic);
    surface::SelfAffineSpec spec;
    spec.hurst = 0.8;
    spec.short_cutoff = 4e-6;  // m
    spec.rms_slope = 0.1;
    spec.seed = 42;
    const Eigen::ArrayXd heights = surface::make_self_affine_surface(grid, spec);
    const surface::SurfaceStatistics roughness = surface::surface_statistics(grid, {heights.data(), grid.size()});
    std::printf("surface: rms height %.3g m, rms slope %.3g\n", roughness.rms_height, roughness.rms_slope);

    // 2. The default solver (Polonsky-Keer, Fourier-preconditioned, on the
    //    FFT operator) for a rubber-like E* = 10 MPa.
    const double e_star = 1e7;  // Pa
    const std::unique_ptr<ContactSolver> solver = solvers::make_solver(grid, e_star, solvers::SolverOptions{});

    // 3. Mean pressures p = x E* h'_rms for x from 0.005 to 0.05, solved in
    //    order, each step warm-started from the previous one.
    std::vector<double> pressures;
    for (const double x : {0.005, 0.01, 0.02, 0.05}) pressures.push_back(x * e_star * roughness.rms_slope);
    const Eigen::ArrayXd gap = solvers::initial_gap(grid, {heights.data(), grid.size()});
    const std::vector<analysis::SweepStep> steps =
        analysis::run_load_sweep(*solver, grid, {gap.data(), grid.size()}, ControlMode::mean_pressure, pressures);

    // 4. A/A0 over p / (E* h'_rms): kappa, about 2 at small loads.
    for (const analysis::SweepStep& step : steps) {
      if (!step.result.converged()) {
        std::fprintf(stderr, "step at %g Pa did not converge: %s\n", step.loading.value, step.result.message.c_str());
        return 2;
      }
      const double x = step.result.mean_pressure / (e_star * roughness.rms_slope);
      std::printf("p = %8.4g Pa  A/A0 = %.4f  kappa = %.2f  clusters %3lld  mean gap %.3g m  %d iterations%s\n",
                  step.result.mean_pressure, step.statistics.contact_fraction, step.statistics.contact_fraction / x,
                  static_cast<long long>(step.statistics.clusters()), step.statistics.mean_gap, step.result.iterations,
                  step.warm_started ? " (warm start)" : "");
    }

    // 5. The sweep file and its CSV table, readable by scripts/halfspace_plot.py.
    const char* output = argc > 1 ? argv[1] : "library_usage.h5";
    io::ResultMetadata metadata;
    metadata.e_star = e_star;
    metadata.load_mode = "mean_pressure";
    metadata.height_source = "self-affine (H = 0.8, seed = 42), examples/library_usage.cpp";
    metadata.surface_statistics = roughness;
    io::write_sweep_result(output, grid, {heights.data(), grid.size()}, steps, metadata);
    io::write_sweep_csv(io::sweep_csv_path(output), steps);
    std::printf("written: %s, %s\n", output, io::sweep_csv_path(output).c_str());
  } catch (const InputError& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
