// The transient Reynolds film against closed forms: the parallel-plate
// squeeze film, the sphere approaching a flat, the time to squeeze a film
// under a constant load; its mass balance through rupture and reformation;
// and its steady limit.
#include "halfspace/lubrication/transient_film.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/film_forces.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEta = 0.1;     // Pa s
constexpr double kWidth = 0.01;  // m, the 1D films' B = (n - 1) dx

FlowConditions still_film() {
  FlowConditions c;
  c.viscosity = kEta;
  return c;
}

std::vector<TransientStep> run(const Grid& grid, const Eigen::ArrayXd& heights, const FlowConditions& conditions,
                               const TransientFilmOptions& options, TransientOutcome* outcome = nullptr,
                               CavitationSolverOptions solver = {}) {
  std::vector<TransientStep> steps;
  const TransientOutcome o = lubricate_transient(grid, heights, conditions, options, solver,
                                                 [&](const TransientStep& s) { steps.push_back(s); });
  if (outcome != nullptr) *outcome = o;
  EXPECT_EQ(o.status, FilmStatus::converged) << o.message;
  return steps;
}

// Parallel plates approaching at V: p = 6 eta V x (B - x) / h^3 and
// W' = eta V B^3 / h^3 (Hamrock, Schmid & Jacobson 2004, ch. 12). The
// pressure is quadratic, which the three-point scheme holds exactly: nodes
// to the solver's tolerance; the trapezoidal load is low by (dx / B)^2.
TEST(TransientFilmTest, ParallelPlateSqueezeMatchesClosedForm) {
  const std::size_t n = 101;
  const double dx = kWidth / (n - 1), v = 1e-4, h0 = 1e-5;
  const Grid grid = Grid::line(n, dx, Boundary::free);
  for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::bdf2}) {
    TransientFilmOptions options;
    options.time_step = 5e-3;
    options.steps = 8;
    options.initial_separation = h0;
    options.approach_velocity = v;
    options.scheme = scheme;
    const std::vector<TransientStep> steps = run(grid, Eigen::ArrayXd::Zero(n), still_film(), options);
    ASSERT_EQ(steps.size(), 9u);
    for (const TransientStep& s : steps) {
      if (s.step == 0) {
        EXPECT_EQ(s.film.forces.load, 0.0);
        continue;
      }
      const double h = h0 - v * s.time;
      EXPECT_NEAR(s.film.separation, h, 1e-15);
      const double peak = 1.5 * kEta * v * kWidth * kWidth / (h * h * h);
      for (std::size_t i = 0; i < n; ++i) {
        const double x = dx * static_cast<double>(i);
        EXPECT_NEAR(s.film.solution.pressure[i], 6.0 * kEta * v * x * (kWidth - x) / (h * h * h), 1e-8 * peak);
      }
      const double load = kEta * v * std::pow(kWidth, 3) / (h * h * h);
      EXPECT_NEAR(s.film.forces.load, load, 1.01 * (dx / kWidth) * (dx / kWidth) * load) << to_string(scheme);
    }
  }
}

// A sphere of radius R approaching a flat, h = h0 + r^2 / (2R):
// p = 3 eta R V / h^2, and within a circle of radius a the load
// F = 6 pi eta R^2 V (1 / h0 - 1 / h(a)) -> 6 pi eta R^2 V / h0 for h0 << R
// (Reynolds 1886; Chan & Horn 1985). The square domain of half-width L lies
// between the circles a = L and a = sqrt(2) L; at 129^2 nodes (6.4 cells on
// sqrt(2 R h0)) the load is within 1.5% of the closed form at a = L.
TEST(TransientFilmTest, SphereApproachingFlatMatchesReynolds) {
  const double radius = 0.01, h0 = 1e-6, v = 1e-5;
  const double half = std::sqrt(200.0 * radius * h0);  // h(L) = 101 h0
  const std::size_t n = 129;
  const double dx = 2.0 * half / (n - 1);
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(n * n));
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = dx * static_cast<double>(i) - half, y = dx * static_cast<double>(j) - half;
      heights[static_cast<Eigen::Index>(j * n + i)] = -(x * x + y * y) / (2.0 * radius);
    }
  }
  TransientFilmOptions options;
  options.time_step = 1e-3;
  options.steps = 1;
  options.initial_separation = h0 + v * options.time_step;
  options.approach_velocity = v;
  const std::vector<TransientStep> steps = run(grid, heights, still_film(), options);
  ASSERT_EQ(steps.size(), 2u);
  const double h = steps[1].film.separation;
  EXPECT_NEAR(h, h0, 1e-18);
  const double inscribed = 6.0 * std::numbers::pi * kEta * radius * radius * v * (1.0 / h - 1.0 / (101.0 * h));
  EXPECT_NEAR(steps[1].film.forces.load, inscribed, 0.015 * inscribed);
  const double centre = 3.0 * kEta * radius * v / (h * h);
  EXPECT_NEAR(steps[1].film.solution.pressure.maxCoeff(), centre, 0.02 * centre);
}

// Parallel plates under a constant load W' close as
// 1 / h^2 = 1 / h1^2 + 2 W' t / (eta B^3) (integrating W' = -eta B^3 h' / h^3);
// the trapezoidal load of the quadratic pressure is exactly
// eta V B^3 (1 - (dx / B)^2) / h^3, the B^3 of the comparison:
// over 100 steps BDF2 follows it to 1e-3 (1e-4 at the end), backward Euler to 1e-2.
TEST(TransientFilmTest, ConstantLoadSqueezeTimeMatchesClosedForm) {
  const std::size_t n = 41;
  const double dx = kWidth / (n - 1), h1 = 1e-5, load = 1.5e3;  // N/m: h1 -> h1 / 2 in 1 s
  const Grid grid = Grid::line(n, dx, Boundary::free);
  const double b3 = std::pow(kWidth, 3) * (1.0 - (dx / kWidth) * (dx / kWidth));
  const auto closed_form = [&](double t) { return 1.0 / std::sqrt(1.0 / (h1 * h1) + 2.0 * load * t / (kEta * b3)); };
  double errors[2] = {0.0, 0.0};  // the largest relative error in h: backward Euler, BDF2
  double finals[2] = {0.0, 0.0};  // at t = 1 s
  for (const TimeScheme scheme : {TimeScheme::backward_euler, TimeScheme::bdf2}) {
    TransientFilmOptions options;
    options.time_step = 0.01;
    options.steps = 100;
    options.initial_separation = h1;
    options.load = LoadControlOptions{.load = load};
    options.scheme = scheme;
    const std::vector<TransientStep> steps = run(grid, Eigen::ArrayXd::Zero(n), still_film(), options);
    ASSERT_EQ(steps.size(), 101u);
    double worst = 0.0;
    for (const TransientStep& s : steps) {
      if (s.step > 0) {
        EXPECT_NEAR(s.film.forces.load, load, 1e-7 * load);
      }
      worst = std::max(worst, std::abs(s.film.separation / closed_form(s.time) - 1.0));
    }
    EXPECT_NEAR(steps.back().film.separation, 0.5 * h1, 0.01 * h1);  // the closed form's h2 at t = 1 s
    errors[scheme == TimeScheme::bdf2] = worst;
    finals[scheme == TimeScheme::bdf2] = std::abs(steps.back().film.separation / closed_form(1.0) - 1.0);
  }
  // BDF2's largest error is its backward-Euler first step's (second order
  // locally); by t = 1 s it has fallen to 1e-5, backward Euler's 4e-3.
  EXPECT_LT(errors[1], 1e-3);
  EXPECT_LT(finals[1], 1e-4);
  EXPECT_LT(errors[0], 1e-2);
  EXPECT_LT(finals[1], 0.01 * finals[0]);
}

// A parabolic slider whose separation oscillates: its divergent half
// cavitates and the film ruptures and reforms as it breathes. Backward
// Euler's balance, (V1 - V0) / dt = inflow - outflow, holds over the whole
// film at every step to the solver's tolerance (the fluxes telescope).
TEST(TransientFilmTest, OscillatingSqueezeConservesMassThroughCavitation) {
  const std::size_t n = 201;
  const double length = 0.002, radius = 0.02, h0 = 1e-5, dt = 2e-4;
  const double dx = length / (n - 1);
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double x = dx * static_cast<double>(i) - 0.5 * length;
    heights[static_cast<Eigen::Index>(i)] = -x * x / (2.0 * radius);
  }
  FlowConditions conditions = still_film();
  conditions.entrainment_velocity = {1.0, 0.0};
  TransientFilmOptions options;
  options.time_step = dt;
  options.steps = 40;
  options.initial_separation = h0;
  options.scheme = TimeScheme::backward_euler;
  std::vector<double> history;
  for (int k = 1; k <= options.steps; ++k)
    history.push_back(h0 * (1.0 + 0.6 * std::sin(2.0 * std::numbers::pi * k / 20.0)));
  options.separation_history = history;
  CavitationSolverOptions solver;
  solver.tolerance = 1e-13;
  const std::vector<TransientStep> steps = run(grid, heights, conditions, options, nullptr, solver);
  ASSERT_EQ(steps.size(), 41u);
  double least = 1.0, most = 0.0;
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const FilmForces& f = steps[k].film.forces;
    const double change = (steps[k].fluid_volume - steps[k - 1].fluid_volume) / dt;
    EXPECT_NEAR(change, f.inflow - f.outflow, 1e-9 * std::max(f.inflow, f.outflow)) << "step " << k;
    least = std::min(least, f.cavitated_fraction);
    most = std::max(most, f.cavitated_fraction);
  }
  EXPECT_GT(most, least + 0.05);  // the cavitated zone grows and shrinks
  EXPECT_GT(least, 0.0);
}

// Plates that part cavitate everywhere and keep their fluid (h theta stays);
// brought back, the film refills exactly where it started.
TEST(TransientFilmTest, PartingPlatesKeepTheirFluid) {
  const std::size_t n = 51;
  const Grid grid = Grid::line(n, kWidth / (n - 1), Boundary::free);
  TransientFilmOptions options;
  options.time_step = 1e-3;
  options.steps = 4;
  options.initial_separation = 1e-5;
  options.separation_history = std::vector<double>{1.5e-5, 2e-5, 1.5e-5, 1e-5};
  const std::vector<TransientStep> steps = run(grid, Eigen::ArrayXd::Zero(n), still_film(), options);
  ASSERT_EQ(steps.size(), 5u);
  for (const TransientStep& s : steps)
    EXPECT_NEAR(s.fluid_volume, steps[0].fluid_volume, 1e-12 * steps[0].fluid_volume);
  EXPECT_NEAR(steps[2].film.solution.fluid_fraction[n / 2], 0.5, 1e-12);
  EXPECT_EQ(steps[2].film.forces.load, 0.0);
  EXPECT_NEAR(steps[4].film.solution.fluid_fraction[n / 2], 1.0, 1e-12);
}

// At a constant separation the steady film is the stepping's fixed point,
// and at a vanishing rate (dt -> infinity) a step is the steady solve.
TEST(TransientFilmTest, SteadyLimitEqualsSteadySolver) {
  const std::size_t n = 201;
  const double length = 0.01, dx = length / (n - 1);
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd heights(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double x = dx * static_cast<double>(i) - 0.5 * length;
    heights[static_cast<Eigen::Index>(i)] = -x * x / 0.04;
  }
  FlowConditions conditions = still_film();
  conditions.entrainment_velocity = {1.0, 0.0};
  const LubricatedFilm steady = lubricate_at_separation(grid, heights, conditions, 1e-5);
  ASSERT_TRUE(steady.solution.converged());
  for (const double dt : {1e-4, 1e12}) {
    TransientFilmOptions options;
    options.time_step = dt;
    options.steps = 3;
    options.initial_separation = 1e-5;
    options.approach_velocity = 0.0;
    const std::vector<TransientStep> steps = run(grid, heights, conditions, options);
    const double peak = steady.solution.pressure.maxCoeff();
    EXPECT_LT((steps.back().film.solution.pressure - steady.solution.pressure).abs().maxCoeff(), 1e-8 * peak);
    EXPECT_LT((steps.back().film.solution.fluid_fraction - steady.solution.fluid_fraction).abs().maxCoeff(), 1e-8);
  }
  EXPECT_GT(steady.forces.cavitated_fraction, 0.2);
}

TEST(TransientFilmTest, RejectsInvalidOptions) {
  const Grid grid = Grid::line(11, 1e-3, Boundary::free);
  const auto reject = [&](const TransientFilmOptions& options, const char* option) {
    try {
      lubricate_transient(grid, Eigen::ArrayXd::Zero(11), still_film(), options, {}, [](const TransientStep&) {});
      ADD_FAILURE() << "accepted invalid " << option;
    } catch (const OptionError& error) {
      EXPECT_EQ(error.option(), option);
    }
  };
  TransientFilmOptions good;
  good.time_step = 1e-3;
  good.steps = 2;
  good.initial_separation = 1e-5;
  good.approach_velocity = 1e-3;
  TransientFilmOptions o = good;
  o.time_step = 0.0;
  reject(o, "time_step");
  o = good;
  o.steps = 0;
  reject(o, "steps");
  o = good;
  o.approach_velocity = 5e-3;  // touches within 2 ms
  reject(o, "approach_velocity");
  o = good;
  o.separation_history = std::vector<double>{1e-5, 1e-5};  // two drivers
  reject(o, "approach_velocity");
  o = good;
  o.approach_velocity.reset();
  o.separation_history = std::vector<double>{1e-5};
  reject(o, "separation_history");
  o.separation_history = std::vector<double>{1e-5, -1.0};
  reject(o, "separation_history");
  EXPECT_THROW(parse_time_scheme("crank-nicolson"), InputError);
  EXPECT_EQ(parse_time_scheme("bdf2"), TimeScheme::bdf2);
}

}  // namespace
}  // namespace halfspace::lubrication
