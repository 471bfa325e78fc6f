// Grid sequencing of the EHL film (ElasticFilmOptions::grid_sequencing):
// the film started from the coarser grids' converges to the same film as
// the cold start (the dry contact), in fewer fine Newton steps, and lands
// on Hamrock & Dowson (1977) as the cold one does.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "support/analytic_solutions.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEStar = 1.1e11;    // Pa: steel on steel, E' = 2.2e11
constexpr double kRadius = 0.01;     // m
constexpr double kViscosity = 0.04;  // Pa s
// Hamrock & Dowson's groups of the existing point-contact validation.
constexpr double kLoadParameter = 3e-7;  // W = w / (E' R^2)
constexpr double kSpeedParameter = 1e-11;
constexpr double kMaterialParameter = 5000;

// A point contact on an n x n grid over x in [-3.5a, 1.5a], y in [-2.5a,
// 2.5a] (a the Hertz radius), as bench/ehl/ehl_scaling.cpp lays it out.
ElasticFilm solve_point(std::size_t n, bool sequencing, int max_iterations = ElasticFilmOptions{}.max_iterations) {
  const double e_prime = 2.0 * kEStar;
  const double load = kLoadParameter * e_prime * kRadius * kRadius;
  const double a = testing::hertz_point(load, kRadius, kEStar).radius;
  const double dx = 5.0 * a / static_cast<double>(n - 1);
  const auto upstream = static_cast<std::size_t>(std::lround(3.5 * a / dx));
  const std::size_t half = (n - 1) / 2;
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n * n));
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
      const double y = (static_cast<double>(j) - static_cast<double>(half)) * dx;
      gap[static_cast<Eigen::Index>(j * n + i)] = (x * x + y * y) / (2.0 * kRadius);
    }
  }
  FlowConditions conditions;
  conditions.viscosity = kViscosity;
  conditions.entrainment_velocity = {kSpeedParameter * e_prime * kRadius / kViscosity, 0.0};
  const LubricantLaws laws{.piezoviscosity = Piezoviscosity::roelands,
                           .pressure_viscosity = kMaterialParameter / e_prime,
                           .compressibility = Compressibility::dowson_higginson};
  FftInfluenceOperator op(grid, kEStar);
  ElasticFilmOptions options{.load = load, .grid_sequencing = sequencing};
  options.max_iterations = max_iterations;
  return solve_elastic_film(op, gap, conditions, laws, options);
}

// Hamrock & Dowson's (1977) fit (k = 1) and the tolerances of
// elastic_film_test.cpp's point contact beyond the dense limit: the fit
// deviates from their own films by a few percent; the minimum, in the side
// lobes, converges slowly with the grid.
double hamrock_dowson_central() {
  return testing::hamrock_dowson_point(kSpeedParameter, kMaterialParameter, kLoadParameter).central;
}
double hamrock_dowson_minimum() {
  return testing::hamrock_dowson_point(kSpeedParameter, kMaterialParameter, kLoadParameter).minimum;
}
constexpr double kHamrockDowsonCentralTolerance = 0.05;
constexpr double kHamrockDowsonMinimumTolerance = 0.12;

// Both films stop at a relative mass residual of 1e-8 (GMRES steps to
// 1e-9): the same discrete solution, so films, pressures and h0 agree far
// inside 1e-6 of each field's largest value.
constexpr double kSameFilm = 1e-6;

TEST(FilmGridSequenceTest, SequencedFilmEqualsColdFilm) {
  const ElasticFilm cold = solve_point(48, false);
  const ElasticFilm sequenced = solve_point(48, true);
  ASSERT_TRUE(cold.converged()) << cold.message;
  ASSERT_TRUE(sequenced.converged()) << sequenced.message;
  EXPECT_EQ(cold.coarse_levels, 0);
  EXPECT_EQ(sequenced.coarse_levels, 1);  // 48^2 = 2304 nodes from 24^2 = 576
  EXPECT_GT(sequenced.coarse_iterations, 0);
  EXPECT_FALSE(sequenced.sequencing_fell_back);
  Eigen::Index where = 0;
  const double film = (cold.film - sequenced.film).abs().maxCoeff(&where) / cold.film.maxCoeff();
  EXPECT_LT(film, kSameFilm) << "largest film difference at node " << where;
  const double pressure = (cold.pressure - sequenced.pressure).abs().maxCoeff(&where) / cold.pressure.maxCoeff();
  EXPECT_LT(pressure, kSameFilm) << "largest pressure difference at node " << where;
  EXPECT_LT(std::abs(cold.offset - sequenced.offset), kSameFilm * cold.film.maxCoeff());
}

// At 25 cells per Hertz radius the cold start takes 16 Newton steps
// (docs/development-log.md); the start interpolated from 64^2 leaves the fine
// grid the discretisation difference: 4 steps on 2 coarse levels with the
// line search on the bent path, 11 on the straight one, where every other
// step was cut short by nodes it carried across the cavitation switch
// (docs/development-log.md, 2026-12-04, forty-fourth session).
constexpr int kMostSequencedFineSteps = 6;

TEST(FilmGridSequenceTest, CoarseStartSavesFineNewtonSteps) {
  const ElasticFilm cold = solve_point(128, false);
  const ElasticFilm sequenced = solve_point(128, true);
  ASSERT_TRUE(cold.converged()) << cold.message;
  ASSERT_TRUE(sequenced.converged()) << sequenced.message;
  EXPECT_EQ(sequenced.coarse_levels, 2);
  EXPECT_LT(sequenced.iterations, cold.iterations);
  EXPECT_LE(sequenced.iterations, kMostSequencedFineSteps);
  EXPECT_LT(sequenced.krylov_iterations, cold.krylov_iterations);
  EXPECT_NEAR(sequenced.central_film_thickness / cold.central_film_thickness, 1.0, kSameFilm);
  EXPECT_NEAR(sequenced.minimum_film_thickness / cold.minimum_film_thickness, 1.0, kSameFilm);
  EXPECT_NEAR(sequenced.central_film_thickness / kRadius / hamrock_dowson_central(), 1.0,
              kHamrockDowsonCentralTolerance);
  EXPECT_NEAR(sequenced.minimum_film_thickness / kRadius / hamrock_dowson_minimum(), 1.0,
              kHamrockDowsonMinimumTolerance);
}

// Odd cell counts have no coarser grid of the same domain, and small grids
// take the dense path: both solve cold.
TEST(FilmGridSequenceTest, OddOrSmallGridsSolveCold) {
  const ElasticFilm odd = solve_point(49, true);
  ASSERT_TRUE(odd.converged()) << odd.message;
  EXPECT_EQ(odd.coarse_levels, 0);
  const ElasticFilm small = solve_point(32, true);
  ASSERT_TRUE(small.converged()) << small.message;
  EXPECT_EQ(small.coarse_levels, 0);
}

// A film that fails on an odd grid says that the grid's shape kept it from
// grid sequencing and which even grid would not; an even grid's failure
// does not.
TEST(FilmGridSequenceTest, OddGridFailureNamesTheEvenGrid) {
  const ElasticFilm odd = solve_point(49, true, 2);
  ASSERT_FALSE(odd.converged());
  EXPECT_NE(odd.message.find("the 49x49 grid has an odd node count"), std::string::npos) << odd.message;
  EXPECT_NE(odd.message.find("an even grid such as 50x50"), std::string::npos) << odd.message;
  const ElasticFilm even = solve_point(64, true, 2);
  ASSERT_FALSE(even.converged());
  EXPECT_EQ(even.message.find("odd node count"), std::string::npos) << even.message;
}

}  // namespace
}  // namespace halfspace::lubrication
