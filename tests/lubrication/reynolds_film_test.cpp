// The rigid Reynolds film with mass-conserving cavitation against closed
// forms (inclined slider, cylinder on plane), its flux balance, Lemke's
// dense LCP, and the 2D film against the 1D one.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/film_forces.hpp"
#include "halfspace/lubrication/lemke_film.hpp"
#include "halfspace/lubrication/load_control.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEta = 0.1;  // Pa s
constexpr double kU = 1.0;    // m/s entrainment
// Second-order scheme: 801 nodes resolve the slider's load to ~1e-5.
constexpr double kSliderLoadTolerance = 1e-4;
// Rupture is resolved to a cell: load within 0.5% at 1601 nodes.
constexpr double kCylinderLoadTolerance = 5e-3;
// Mass balance telescopes exactly: flows agree to the solver tolerance.
constexpr double kFlowBalanceTolerance = 1e-9;

FlowConditions conditions_along_x() {
  FlowConditions c;
  c.viscosity = kEta;
  c.entrainment_velocity = {kU, 0.0};
  return c;
}

// Inclined slider h = ho (1 + K (1 - x / L)): p(X) = 12 eta U L K X (1 - X) /
// (ho^2 (2 + K) (1 + K - K X)^2), W' = 12 eta U L^2 / (ho^2 K^2) (ln(1 + K) -
// 2K / (2 + K)) (Hamrock, Schmid & Jacobson 2004, ch. 8, with U the mean velocity).
double slider_load(double length, double ho, double k) {
  return 12.0 * kEta * kU * length * length / (ho * ho * k * k) * (std::log(1.0 + k) - 2.0 * k / (2.0 + k));
}

FilmSolution solve_slider(std::size_t n, double length, double ho, double k, Eigen::ArrayXd& film) {
  const Grid grid = Grid::line(n, length / static_cast<double>(n - 1), Boundary::free);
  film.resize(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) film[i] = ho * (1.0 + k * (1.0 - static_cast<double>(i) / (n - 1)));
  const ReynoldsStencil stencil(grid, film, conditions_along_x());
  return solve_cavitating_film(stencil);
}

TEST(ReynoldsFilmTest, InclinedSliderMatchesClosedForm) {
  const double length = 0.01, ho = 1e-5, k = 1.0;
  const std::size_t n = 801;
  Eigen::ArrayXd film;
  const FilmSolution s = solve_slider(n, length, ho, k, film);
  ASSERT_TRUE(s.converged()) << s.message;
  const Grid grid = Grid::line(n, length / (n - 1), Boundary::free);
  const FilmForces f = film_forces(ReynoldsStencil(grid, film, conditions_along_x()), s);
  double worst = 0.0;
  std::size_t where = 0;
  const double scale = 12.0 * kEta * kU * length / (ho * ho);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / (n - 1);
    const double exact = scale * k * x * (1 - x) / ((2 + k) * std::pow(1 + k - k * x, 2));
    if (std::abs(s.pressure[i] - exact) > worst) worst = std::abs(s.pressure[i] - exact), where = i;
  }
  const double w = slider_load(length, ho, k);
  std::printf("slider: %d sweeps, worst pressure error %.3g of %.3g at node %zu, load %.10g vs %.10g\n", s.iterations,
              worst, s.pressure.maxCoeff(), where, f.load, w);
  EXPECT_LT(worst, kSliderLoadTolerance * s.pressure.maxCoeff());
  EXPECT_NEAR(f.load, w, kSliderLoadTolerance * w);
  EXPECT_EQ(f.cavitated_fraction, 0.0);
  EXPECT_NEAR(f.inflow, f.outflow, kFlowBalanceTolerance * f.inflow);
}

TEST(ReynoldsFilmTest, InclinedSliderConvergesAtSecondOrder) {
  const double length = 0.01, ho = 1e-5, k = 1.0;
  double errors[2];
  const std::size_t sizes[2] = {51, 101};
  for (int level = 0; level < 2; ++level) {
    Eigen::ArrayXd film;
    const FilmSolution s = solve_slider(sizes[level], length, ho, k, film);
    ASSERT_TRUE(s.converged());
    const Grid grid = Grid::line(sizes[level], length / (sizes[level] - 1), Boundary::free);
    errors[level] =
        std::abs(film_forces(ReynoldsStencil(grid, film, conditions_along_x()), s).load - slider_load(length, ho, k));
  }
  const double order = std::log2(errors[0] / errors[1]);
  std::printf("slider load errors %.3g, %.3g: order %.3f\n", errors[0], errors[1], order);
  EXPECT_NEAR(order, 2.0, 0.1);
}

// Cylinder on plane, h = h0 (1 + xi^2), x = sqrt(2 R h0) xi, flooded inlet at
// xi_in, Reynolds (Swift–Stieber) rupture at xi_m: the JFO film without
// reformation. With J2, J3 the antiderivatives of (1 + xi^2)^-2, ^-3,
// p' = 12 eta U sqrt(2 R h0) / h0^2 (xi^2 - xi_m^2) / (1 + xi^2)^3, p(xi_in) = 0
// = p(xi_m) fixes xi_m, and W' = 24 eta U R / h0 [G]_{xi_in}^{xi_m} with
// G = -(1/2)(-1/t + (1 + xi_m^2) / (2 t^2)), t = 1 + xi^2 (integration by
// parts). xi_in -> -inf gives xi_m = 0.4751, W' = 4.895 eta U R / h0
// (Martin 1916; 2.448 eta (u1 + u2) R / h0).
struct CylinderReference {
  double rupture = 0.0;      // xi_m
  double load_factor = 0.0;  // W' h0 / (eta U R)
};

CylinderReference cylinder_reference(double xi_in) {
  const auto j2 = [](double t) { return t / (2 * (1 + t * t)) + std::atan(t) / 2; };
  const auto j3 = [](double t) {
    return t / (4 * std::pow(1 + t * t, 2)) + 3 * t / (8 * (1 + t * t)) + 3 * std::atan(t) / 8;
  };
  const auto f = [&](double m) { return (j2(m) - j2(xi_in)) - (1 + m * m) * (j3(m) - j3(xi_in)); };
  double a = 0.01, b = 2.0;
  for (int i = 0; i < 200; ++i) {
    const double c = 0.5 * (a + b);
    (f(a) * f(c) <= 0 ? b : a) = c;
  }
  const double m = 0.5 * (a + b);
  const auto g = [&](double t) { return 0.5 * (-1 / (1 + t * t) + (1 + m * m) / (2 * std::pow(1 + t * t, 2))); };
  return {m, -24.0 * (g(m) - g(xi_in))};
}

TEST(ReynoldsFilmTest, CylinderOnPlaneMatchesSwiftStieberSolution) {
  const double radius = 0.01, h0 = 1e-6;
  const double unit = std::sqrt(2 * radius * h0);
  const double xi_in = -4.0, xi_out = 2.0;
  const std::size_t n = 1601;
  const double dx = (xi_out - xi_in) * unit / (n - 1);
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd film(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = xi_in + i * dx / unit;
    film[i] = h0 * (1 + xi * xi);
  }
  const ReynoldsStencil stencil(grid, film, conditions_along_x());
  const FilmSolution s = solve_cavitating_film(stencil);
  ASSERT_TRUE(s.converged()) << s.message;
  const FilmForces f = film_forces(stencil, s);
  const CylinderReference ref = cylinder_reference(xi_in);
  const CylinderReference martin = cylinder_reference(-1e9);
  std::size_t rupture = 0;
  while (rupture < n && !(s.pressure[rupture] == 0.0 && s.fluid_fraction[rupture] < 1.0 && rupture > n / 4)) ++rupture;
  const double rupture_xi = xi_in + rupture * dx / unit;
  const double load_factor = f.load * h0 / (kEta * kU * radius);
  std::printf("cylinder: %d sweeps, load factor %.6f vs %.6f (Martin limit %.6f, rupture %.4f), rupture %.4f vs %.4f\n",
              s.iterations, load_factor, ref.load_factor, martin.load_factor, martin.rupture, rupture_xi, ref.rupture);
  EXPECT_NEAR(martin.load_factor, 4.895, 1e-3);  // the reference's own limit, as published
  EXPECT_NEAR(load_factor, ref.load_factor, kCylinderLoadTolerance * ref.load_factor);
  EXPECT_NEAR(rupture_xi, ref.rupture, 2 * dx / unit);
  EXPECT_NEAR(f.inflow, f.outflow, kFlowBalanceTolerance * f.inflow);
  EXPECT_TRUE(satisfies_complementarity(s.pressure, s.fluid_fraction));
}

// A film of two waves, h = (1.5 + cos(4 pi x / L)) um: it ruptures where the first wave diverges and
// reforms in the second's convergent part, where pressure builds again. Every face carries the same flow (steady mass
// conservation), and Lemke's LCP gives the same nodes.
Eigen::ArrayXd wavy_film(std::size_t n) {
  Eigen::ArrayXd film(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / (n - 1);
    film[i] = 1e-6 * (1.5 + std::cos(4.0 * std::numbers::pi * x));
  }
  return film;
}

TEST(ReynoldsFilmTest, WavyFilmConservesMassThroughReformation) {
  const std::size_t n = 401;
  const Grid grid = Grid::line(n, 1e-2 / (n - 1), Boundary::free);
  const Eigen::ArrayXd film = wavy_film(n);
  const ReynoldsStencil stencil(grid, film, conditions_along_x());
  const FilmSolution s = solve_cavitating_film(stencil);
  ASSERT_TRUE(s.converged()) << s.message;
  const FilmForces f = film_forces(stencil, s);
  double lowest = 1.0, reformed_pressure = 0.0;
  for (std::size_t i = 0; i < n; ++i) lowest = std::min(lowest, s.fluid_fraction[i]);
  for (std::size_t i = n / 2; i < n; ++i) reformed_pressure = std::max(reformed_pressure, s.pressure[i]);
  double worst = 0.0;
  const double flow = stencil.east_flow(0, s.pressure, s.fluid_fraction);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    worst = std::max(worst, std::abs(stencil.east_flow(i, s.pressure, s.fluid_fraction) - flow));
  }
  std::printf("wavy film: %d sweeps, lowest theta %.4f, cavitated %.3f, face flow spread %.3g of %.3g\n", s.iterations,
              lowest, f.cavitated_fraction, worst, flow);
  EXPECT_LT(lowest, 0.9);             // it cavitates after the first wave
  EXPECT_GT(reformed_pressure, 0.0);  // and pressure builds again downstream
  EXPECT_LT(worst, kFlowBalanceTolerance * flow);
}

TEST(ReynoldsFilmTest, LemkeMatchesProjectedSorOnWavyFilm) {
  // Lemke's pivots are exact to rounding; SOR is run tighter for the comparison.
  constexpr double kAgreement = 1e-10;
  const std::size_t n = 41;
  const Grid grid = Grid::line(n, 1e-2 / (n - 1), Boundary::free);
  const ReynoldsStencil stencil(grid, wavy_film(n), conditions_along_x());
  const FilmSolution sor = solve_cavitating_film(stencil, {.tolerance = 1e-14});
  const FilmSolution lemke = solve_film_lemke(stencil);
  ASSERT_TRUE(sor.converged()) << sor.message;
  ASSERT_TRUE(lemke.converged()) << lemke.message;
  EXPECT_LT(lemke.relative_residual, 1e-12);
  const double p_max = sor.pressure.maxCoeff();
  EXPECT_LT((sor.pressure - lemke.pressure).abs().maxCoeff(), kAgreement * p_max);
  EXPECT_LT((sor.fluid_fraction - lemke.fluid_fraction).abs().maxCoeff(), kAgreement);
  EXPECT_LT(sor.fluid_fraction.minCoeff(), 0.9);
}

TEST(ReynoldsFilmTest, FilmUniformAlongPeriodicYMatchesLineFilm) {
  const std::size_t n = 81, ny = 4;
  const double dx = 1e-2 / (n - 1);
  const Eigen::ArrayXd line_film = wavy_film(n);
  Eigen::ArrayXd plane_film(n * ny);
  for (std::size_t j = 0; j < ny; ++j) plane_film.segment(j * n, n) = line_film;
  FlowConditions c = conditions_along_x();
  const FilmSolution line =
      solve_cavitating_film(ReynoldsStencil(Grid::line(n, dx, Boundary::free), line_film, c), {.tolerance = 1e-13});
  c.boundary.y = AxisBoundary::periodic;
  const FilmSolution plane = solve_cavitating_film(
      ReynoldsStencil(Grid::plane(n, ny, dx, dx, Boundary::free), plane_film, c), {.tolerance = 1e-13});
  ASSERT_TRUE(line.converged() && plane.converged());
  for (std::size_t j = 0; j < ny; ++j) {
    EXPECT_LT((plane.pressure.segment(j * n, n) - line.pressure).abs().maxCoeff(), 1e-9 * line.pressure.maxCoeff());
  }
}

TEST(ReynoldsFilmTest, LoadControlFindsSeparationOfSlider) {
  const std::size_t n = 201;
  const double length = 0.01;
  const Grid grid = Grid::line(n, length / (n - 1), Boundary::free);
  Eigen::ArrayXd heights(n);  // a ramp rising 10 um towards the outlet
  for (std::size_t i = 0; i < n; ++i) heights[i] = 1e-5 * static_cast<double>(i) / (n - 1);
  const double ho = 1e-5;  // K = 1
  const LubricatedFilm at = lubricate_at_separation(grid, heights, conditions_along_x(), ho);
  const LubricatedFilm found =
      lubricate_at_load(grid, heights, conditions_along_x(), {.load = at.forces.load, .relative_tolerance = 1e-9});
  ASSERT_TRUE(found.solution.converged()) << found.solution.message;
  std::printf("load control: %d film solves, separation %.10g vs %.10g\n", found.film_solves, found.separation, ho);
  EXPECT_NEAR(found.separation, ho, 1e-8 * ho);
}

TEST(ReynoldsFilmTest, RejectsInvalidConditions) {
  const Grid grid = Grid::line(11, 1e-3, Boundary::free);
  FlowConditions c = conditions_along_x();
  c.viscosity = -1.0;
  try {
    c.validate(grid);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("viscosity = -1"), std::string::npos);
  }
  c = conditions_along_x();
  c.boundary.x = AxisBoundary::periodic;
  EXPECT_THROW(c.validate(grid), InputError);
  EXPECT_THROW(CavitationSolverOptions{.relaxation = 2.0}.validate(), InputError);
  EXPECT_THROW(ReynoldsStencil(grid, Eigen::ArrayXd::Zero(11), conditions_along_x()), InputError);
}

}  // namespace
}  // namespace halfspace::lubrication
