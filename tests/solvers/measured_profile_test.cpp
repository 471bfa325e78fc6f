// The default solver (pk-multilevel) and pk-fourier on measured surfaces, a
// Dektak profile (1D) and an AFM map crop (2D), free and periodic, from light
// loads to nearly full contact: each must converge, satisfy the contact
// conditions and carry the load, and agree with an independent solver: the
// dense Lemke path on small grids, plain Polonsky-Keer on the full profile
// and the 2D map.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/surface_solve.hpp"
#include "halfspace/surface/detrend.hpp"
#include "io/hdf5_test_support.hpp"
#include "support/contact_checks.hpp"
#include "support/pk_solvers.hpp"
#include "support/program_run.hpp"

namespace halfspace::solvers {
namespace {

namespace fs = std::filesystem;
using testing::expect_contact_conditions;

const fs::path kDataDir = HALFSPACE_TEST_DATA_DIR;
constexpr double kEStar = 1e9;  // Pa, a polymer against a hard counterface
// Force balance holds to rounding under load control.
constexpr double kForceBalance = 1e-10;

struct Surface {
  Grid grid;
  Eigen::ArrayXd gap;
};

// The file's heights less their least-squares quadratic, as the initial gap.
Surface measured(const std::string& file, Boundary boundary) {
  HeightMap map = io::read_height_map(kDataDir / file);
  surface::detrend(map, surface::Detrend::curvature);
  const Grid grid =
      map.dimension == 1 ? Grid::line(map.nx, map.dx, boundary) : Grid::plane(map.nx, map.ny, map.dx, map.dy, boundary);
  return {grid, solvers::initial_gap(grid, {map.heights.data(), grid.size()})};
}

SolveResult solve(const std::string& solver, const Surface& s, double mean_pressure, int max_iterations = 10000) {
  SolverOptions settings = testing::test_options(parse_solver_type(solver));
  settings.max_iterations = max_iterations;
  return make_solver(s.grid, kEStar, settings)
      ->solve({s.gap.data(), s.grid.size()}, Loading::mean_pressure(mean_pressure));
}

// Converged, p >= 0, no interpenetration and a closed gap on the contact
// set to 1e-6 of the gap's range (the residual is 1e-10 of the gap scale),
// and the load carried.
void expect_valid(const SolveResult& result, const Surface& s, double mean_pressure, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_TRUE(result.converged()) << result.message;
  expect_contact_conditions(result, 1e-6 * (s.gap.maxCoeff() - s.gap.minCoeff()));
  EXPECT_NEAR(result.mean_pressure, mean_pressure, kForceBalance * mean_pressure);
}

std::string label(const std::string& solver, const Surface& s, double mean_pressure) {
  return solver + ", " + std::string(to_string(s.grid.boundary())) + ", " + std::to_string(mean_pressure) + " Pa";
}

// The largest pressure difference relative to the reference's peak.
double pressure_difference(const SolveResult& result, const SolveResult& reference) {
  return (result.pressure - reference.pressure).abs().maxCoeff() / reference.max_pressure;
}

const std::vector<std::string> kSolvers = {"pk-multilevel", "pk-fourier"};

// The Dektak profile, 9600 points (1e5-1e6 Pa used to cycle at residual
// 2-6e-2), from 0.1 % to 99.7 % contact.
TEST(MeasuredProfileTest, DektakProfileConvergesFromLightLoadsToNearlyFullContact) {
  for (const Boundary boundary : {Boundary::free, Boundary::periodic}) {
    const Surface s = measured("dektak-1.csv", boundary);
    for (const double load : {1e4, 1e5, 1e6, 3e7}) {
      SolveResult first;
      for (const std::string& solver : kSolvers) {
        const SolveResult result = solve(solver, s, load);
        expect_valid(result, s, load, label(solver, s, load));
        std::printf("%s: %d iterations, contact %.4f\n", label(solver, s, load).c_str(), result.iterations,
                    result.contact_fraction);
        if (first.pressure.size() == 0) {
          first = result;
        } else {
          // Two solutions to residual 1e-10 of the same problem.
          EXPECT_LE(pressure_difference(result, first), 1e-6) << label(solver, s, load);
        }
      }
    }
  }
}

// Against plain Polonsky-Keer, the paper's algorithm, where it converges:
// the free profile at 3e5 Pa (on the periodic one, and at 1e5 Pa on the free
// one, it cycles itself; at 1e6 Pa it needs more than 10,000 iterations).
TEST(MeasuredProfileTest, DektakProfileMatchesPlainPolonskyKeer) {
  const Surface s = measured("dektak-1.csv", Boundary::free);
  const double load = 3e5;
  const SolveResult reference = solve("pk", s, load);
  expect_valid(reference, s, load, label("pk", s, load));
  for (const std::string& solver : kSolvers) {
    const SolveResult result = solve(solver, s, load);
    expect_valid(result, s, load, label(solver, s, load));
    const double difference = pressure_difference(result, reference);
    std::printf("%s: %d iterations against pk's %d, max |dp| %.1e of the peak\n", label(solver, s, load).c_str(),
                result.iterations, reference.iterations, difference);
    EXPECT_LE(difference, 1e-6) << label(solver, s, load);
    EXPECT_EQ((result.pressure > 0.0).count(), (reference.pressure > 0.0).count()) << label(solver, s, load);
  }
}

// 256 points of the same instrument against the dense Lemke solution (an
// independent method: pivoting on the assembled matrix), 1 % to full contact.
TEST(MeasuredProfileTest, DektakCropMatchesLemke) {
  for (const Boundary boundary : {Boundary::free, Boundary::periodic}) {
    const Surface s = measured("dektak-1-crop-256.h5", boundary);
    for (const double load : {1e4, 1e5, 1e6, 1e7}) {
      const SolveResult reference = solve("lemke", s, load);
      ASSERT_TRUE(reference.converged()) << reference.message;
      for (const std::string& solver : kSolvers) {
        const SolveResult result = solve(solver, s, load);
        expect_valid(result, s, load, label(solver, s, load));
        const double difference = pressure_difference(result, reference);
        std::printf("%s: %d iterations, contact %.4f, max |dp| %.1e of Lemke's peak\n", label(solver, s, load).c_str(),
                    result.iterations, result.contact_fraction, difference);
        // Lemke solves the LCP to rounding; the iteration to residual 1e-10.
        EXPECT_LE(difference, 1e-6) << label(solver, s, load);
      }
    }
  }
}

// A 48 x 64 crop of an AFM map, against plain Polonsky-Keer, 3 % to 99.5 %
// contact.
TEST(MeasuredProfileTest, AfmMapCropMatchesPlainPolonskyKeer) {
  for (const Boundary boundary : {Boundary::free, Boundary::periodic}) {
    const Surface s = measured("di-5-crop-48x64.h5", boundary);
    for (const double load : {1e6, 1e7, 3e7, 1e8, 3e8}) {
      const SolveResult reference = solve("pk", s, load);
      expect_valid(reference, s, load, label("pk", s, load));
      for (const std::string& solver : kSolvers) {
        const SolveResult result = solve(solver, s, load);
        expect_valid(result, s, load, label(solver, s, load));
        const double difference = pressure_difference(result, reference);
        std::printf("%s: %d iterations, contact %.4f, max |dp| %.1e of pk's peak\n", label(solver, s, load).c_str(),
                    result.iterations, result.contact_fraction, difference);
        EXPECT_LE(difference, 1e-6) << label(solver, s, load);
      }
    }
  }
}

// The issue's command line, which exited 2 with the residual stuck at 5e-2.
TEST(MeasuredProfileTest, IssueReproducerConverges) {
  const test::TempDir dir;
  const testing::ProgramRun run =
      testing::run_program({"solve", "--height-map", (kDataDir / "dektak-1.csv").string(), "--detrend", "curvature",
                            "--boundary", "free", "--E-star", "1e9", "--mean-pressure", "3e5", "--output", "o.h5"},
                           dir.path());
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.out.find("converged"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("0.0758"), std::string::npos) << "contact fraction of plain pk's solution\n" << run.out;
}

}  // namespace
}  // namespace halfspace::solvers
