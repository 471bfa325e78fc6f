// The EHL GMRES's preconditioners (ElasticFilmOptions::preconditioner): the
// multigrid V-cycle and the sparse LU of the Jacobian's sparse part lead
// the Newton iteration to the same film, which differs between them only
// within the solver's tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "support/analytic_solutions.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEStar = 1.1e11;    // Pa: steel on steel, E' = 2.2e11
constexpr double kRadius = 0.01;     // m
constexpr double kViscosity = 0.04;  // Pa s
constexpr double kMaterialParameter = 5000;
constexpr double kSpeedParameter = 1e-11;

FlowConditions rolling() {
  FlowConditions conditions;
  conditions.viscosity = kViscosity;
  conditions.entrainment_velocity = {kSpeedParameter * 2.0 * kEStar * kRadius / kViscosity, 0.0};
  return conditions;
}

LubricantLaws roelands() {
  return {.piezoviscosity = Piezoviscosity::roelands,
          .pressure_viscosity = kMaterialParameter / (2.0 * kEStar),
          .compressibility = Compressibility::dowson_higginson};
}

// A point contact (W = 3e-7) on an n x n grid over x in [-3.5a, 1.5a], y in
// [-2.5a, 2.5a], as bench/ehl/ehl_scaling.cpp lays it out.
ElasticFilm point_contact(std::size_t n, KrylovPreconditioner preconditioner) {
  const double load = 3e-7 * 2.0 * kEStar * kRadius * kRadius;
  const double a = testing::hertz_point(load, kRadius, kEStar).radius;
  const double dx = 5.0 * a / static_cast<double>(n - 1);
  const auto upstream = static_cast<double>(std::lround(3.5 * a / dx));
  const auto half = static_cast<double>((n - 1) / 2);
  const Grid grid = Grid::plane(n, n, dx, dx, Boundary::free);
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n * n));
  for (std::size_t j = 0; j < n; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = (static_cast<double>(i) - upstream) * dx;
      const double y = (static_cast<double>(j) - half) * dx;
      gap[static_cast<Eigen::Index>(j * n + i)] = (x * x + y * y) / (2.0 * kRadius);
    }
  }
  FftInfluenceOperator op(grid, kEStar);
  return solve_elastic_film(op, gap, rolling(), roelands(),
                            {.load = load, .linear_solve = FilmLinearSolve::gmres, .preconditioner = preconditioner});
}

// A line contact (W = 1e-4) at 256 cells per Hertz half-width over x in
// [-4.5b, 1.5b]: 1537 nodes, so that the multigrid has a coarse level (the
// line solve is exact on a 1D grid; the coarse correction is then zero).
ElasticFilm line_contact(KrylovPreconditioner preconditioner) {
  const double load = 1e-4 * 2.0 * kEStar * kRadius;
  const double b = testing::hertz_line(load, kRadius, kEStar).half_width;
  const double cells = 256.0;
  const double dx = b / cells;
  const auto upstream = static_cast<std::size_t>(4.5 * cells);
  const auto n = upstream + static_cast<std::size_t>(1.5 * cells) + 1;
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
    gap[static_cast<Eigen::Index>(i)] = x * x / (2.0 * kRadius);
  }
  FftInfluenceOperator op(grid, kEStar);
  return solve_elastic_film(op, gap, rolling(), roelands(),
                            {.load = load, .linear_solve = FilmLinearSolve::gmres, .preconditioner = preconditioner});
}

// Both Newton iterations stop at a relative mass residual and load error
// of 1e-8: the same discrete film, so h0, the central and minimum films and
// the pressure agree far inside 1e-6 of their scales (the film's largest
// value, the largest pressure).
constexpr double kSameFilm = 1e-6;

void expect_same_film(const ElasticFilm& lu, const ElasticFilm& multigrid) {
  ASSERT_TRUE(lu.converged()) << lu.message;
  ASSERT_TRUE(multigrid.converged()) << multigrid.message;
  EXPECT_TRUE(multigrid.used_krylov);
  const double film_scale = lu.film.maxCoeff();
  EXPECT_LT(std::abs(lu.offset - multigrid.offset), kSameFilm * film_scale);
  EXPECT_LT(std::abs(lu.central_film_thickness - multigrid.central_film_thickness), kSameFilm * film_scale);
  EXPECT_LT(std::abs(lu.minimum_film_thickness - multigrid.minimum_film_thickness), kSameFilm * film_scale);
  Eigen::Index where = 0;
  const double pressure = (lu.pressure - multigrid.pressure).abs().maxCoeff(&where) / lu.pressure.maxCoeff();
  EXPECT_LT(pressure, kSameFilm) << "largest pressure difference at node " << where;
}

TEST(FilmPreconditionerTest, MultigridGivesTheSparseLuFilmOnAPointContact) {
  // 96^2: the multigrid's levels 96^2, 48^2 and 24^2 (solved directly).
  expect_same_film(point_contact(96, KrylovPreconditioner::sparse_lu),
                   point_contact(96, KrylovPreconditioner::multigrid));
}

TEST(FilmPreconditionerTest, MultigridGivesTheSparseLuFilmOnALineContact) {
  expect_same_film(line_contact(KrylovPreconditioner::sparse_lu), line_contact(KrylovPreconditioner::multigrid));
}

TEST(FilmPreconditionerTest, OptionIsValidatedAndParsed) {
  ElasticFilmOptions options{.load = 1.0};
  options.preconditioner = static_cast<KrylovPreconditioner>(7);
  try {
    options.validate();
    ADD_FAILURE() << "an invalid preconditioner was accepted";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "preconditioner");
    EXPECT_NE(std::string(e.what()).find("multigrid, sparse-lu"), std::string::npos) << e.what();
  }
  EXPECT_EQ(parse_krylov_preconditioner("multigrid"), KrylovPreconditioner::multigrid);
  EXPECT_EQ(parse_krylov_preconditioner(to_string(KrylovPreconditioner::sparse_lu)), KrylovPreconditioner::sparse_lu);
  try {
    parse_krylov_preconditioner("ilu");
    ADD_FAILURE() << "'ilu' was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'ilu'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace halfspace::lubrication
