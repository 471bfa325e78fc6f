// The film's shear (film_shear.hpp): the inclined slider's friction against
// its closed form, film_forces' friction on a cavitating film, Eyring and
// the limiting shear stress on a uniform film in closed form, and the EHL
// traction coefficient reaching the limiting shear slope gamma where the
// Hertzian zone is at the cap.
#include "halfspace/lubrication/film_shear.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/lubrication/film_forces.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "support/analytic_solutions.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEta = 0.1;  // Pa s

// Inclined slider h = ho (1 + K (1 - x / L)) with the runner sliding at
// du = u_upper - u_lower (entrainment du / 2, one surface at rest). On the
// lower surface tau = eta du / h - (h / 2) p', so the Couette force is eta du
// L ln(1 + K) / (K ho) and, by parts with h' = -K ho / L and p = 0 at both
// ends, the Poiseuille force -(1/2) int h p' dx = -K ho W' / (2 L), W' =
// 6 eta du L^2 / (ho^2 K^2) (ln(1 + K) - 2K / (2 + K)) (Hamrock, Schmid &
// Jacobson 2004, ch. 8).
TEST(FilmShearTest, InclinedSliderFrictionMatchesClosedForm) {
  const double length = 0.01, ho = 1e-5, k = 1.0, du = 2.0;
  const std::size_t n = 801;
  const Grid grid = Grid::line(n, length / static_cast<double>(n - 1), Boundary::free);
  Eigen::ArrayXd film(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) film[i] = ho * (1.0 + k * (1.0 - static_cast<double>(i) / (n - 1)));
  FlowConditions conditions;
  conditions.viscosity = kEta;
  conditions.entrainment_velocity = {0.5 * du, 0.0};
  conditions.sliding_velocity = {du, 0.0};
  const FilmSolution s = solve_cavitating_film(ReynoldsStencil(grid, film, conditions));
  ASSERT_TRUE(s.converged()) << s.message;
  const FilmShear shear = film_shear(grid, conditions, {}, {}, film, s.pressure, s.fluid_fraction);
  const double load = 6.0 * kEta * du * length * length / (ho * ho * k * k) * (std::log(1.0 + k) - 2.0 * k / (2.0 + k));
  const double couette = kEta * du * length * std::log(1.0 + k) / (k * ho);
  const double poiseuille = -k * ho * load / (2.0 * length);
  std::printf("slider friction: couette %.10g vs %.10g, total %.10g vs %.10g, mu %.6g\n", shear.couette_force[0],
              couette, shear.friction_force[0], couette + poiseuille, shear.friction_coefficient);
  EXPECT_NEAR(shear.couette_force[0], couette, 1e-6 * couette);  // trapezoidal rule on 800 intervals
  EXPECT_NEAR(shear.friction_force[0], couette + poiseuille, 1e-4 * couette);
  EXPECT_NEAR(shear.load, load, 1e-4 * load);
  EXPECT_NEAR(shear.friction_coefficient, (couette + poiseuille) / load, 2e-4 * (couette + poiseuille) / load);
  EXPECT_EQ(shear.limited_fraction, 0.0);
}

// On a cavitating film (a cylinder, rupture and theta < 1 downstream) a
// Newtonian isoviscous shear is film_forces' friction.
TEST(FilmShearTest, NewtonianIsoviscousShearIsFilmForcesFriction) {
  const double radius = 0.01, h0 = 1e-6;
  const std::size_t n = 201;
  const double unit = std::sqrt(2 * radius * h0);
  const double dx = 8.0 * unit / (n - 1);
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd film(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = -4.0 + static_cast<double>(i) * dx / unit;
    film[i] = h0 * (1 + xi * xi);
  }
  FlowConditions conditions;
  conditions.viscosity = kEta;
  conditions.entrainment_velocity = {1.0, 0.0};
  conditions.sliding_velocity = {0.3, 0.0};
  const ReynoldsStencil stencil(grid, film, conditions);
  const FilmSolution s = solve_cavitating_film(stencil);
  ASSERT_TRUE(s.converged()) << s.message;
  const FilmForces forces = film_forces(stencil, s);
  ASSERT_GT(forces.cavitated_fraction, 0.1);
  const FilmShear shear = film_shear(grid, conditions, {}, {}, film, s.pressure, s.fluid_fraction);
  EXPECT_NEAR(shear.friction_force[0], forces.friction_force[0], 1e-14 * std::abs(forces.friction_force[0]));
  EXPECT_NEAR(shear.load, forces.load, 1e-14 * forces.load);
  EXPECT_NEAR(shear.friction_coefficient, forces.friction_coefficient, 1e-14 * forces.friction_coefficient);
}

// A uniform film h under a uniform pressure P (fixed at both ends): no
// pressure gradient, and the Couette stress per unit length is the law's
// closed form at eta0 exp(alpha P) du / h.
TEST(FilmShearTest, EyringAndLimitingShearOnAUniformFilm) {
  const std::size_t n = 11;
  const double length = 1e-3, h = 1e-7, pressure = 5e8, alpha = 2e-8, du = 1.5;
  const Grid grid = Grid::line(n, length / (n - 1), Boundary::free);
  FlowConditions conditions;
  conditions.viscosity = 0.01;
  conditions.entrainment_velocity = {1.0, 0.0};
  conditions.sliding_velocity = {-du, 0.0};
  conditions.boundary.x_low_pressure = conditions.boundary.x_high_pressure = pressure;
  const LubricantLaws barus{.piezoviscosity = Piezoviscosity::barus, .pressure_viscosity = alpha};
  const Eigen::ArrayXd film = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), h);
  const Eigen::ArrayXd p = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), pressure);
  const Eigen::ArrayXd theta = Eigen::ArrayXd::Ones(static_cast<Eigen::Index>(n));
  const double newtonian = 0.01 * std::exp(alpha * pressure) * du / h;

  const FilmShear plain = film_shear(grid, conditions, barus, {}, film, p, theta);
  EXPECT_NEAR(plain.friction_force[0], -newtonian * length, 1e-12 * newtonian * length);

  const ShearLimits eyring{.eyring_stress = 2e6};
  const FilmShear eyring_shear = film_shear(grid, conditions, barus, eyring, film, p, theta);
  const double eyring_stress = 2e6 * std::asinh(newtonian / 2e6);
  EXPECT_NEAR(eyring_shear.friction_force[0], -eyring_stress * length, 1e-12 * eyring_stress * length);
  EXPECT_EQ(eyring_shear.limited_fraction, 1.0);

  const ShearLimits cap{.limiting_shear_stress = 3e6, .limiting_shear_slope = 0.07};
  const FilmShear capped = film_shear(grid, conditions, barus, cap, film, p, theta);
  const double limit = 3e6 + 0.07 * pressure;
  ASSERT_LT(limit, newtonian);
  EXPECT_NEAR(capped.friction_force[0], -limit * length, 1e-12 * limit * length);
  EXPECT_NEAR(capped.friction_coefficient, limit / pressure, 1e-12);
  EXPECT_EQ(capped.shear_y.abs().maxCoeff(), 0.0);
  const FilmShear proportional =
      film_shear(grid, conditions, barus, {.limiting_shear_slope = 0.07}, film, p, theta);  // tau_L = gamma p
  EXPECT_NEAR(proportional.friction_coefficient, 0.07, 1e-12);
}

// EHL line contact (Roelands, Dowson–Higginson; W = 2e-5, U = 1e-11,
// G = 5000) with a cap gamma p (tau_L0 = 1 Pa): pure rolling has no
// Couette traction; sliding, the piezoviscous Newtonian stress exceeds the
// cap in the Hertzian zone but not on the pressure's flanks, where eta(p)
// du / h < gamma p, until the sliding is fast enough to cap every loaded
// node: the traction then is gamma times the load.
TEST(FilmShearTest, EhlTractionReachesTheLimitingShearSlope) {
  const double e_star = 1.1e11, radius = 0.01, eta0 = 0.04, e_prime = 2.0 * e_star;
  const double load = 2e-5 * e_prime * radius;
  const double b = testing::hertz_line(load, radius, e_star).half_width;
  const double cells = 16.0;
  const double dx = b / cells;
  const auto upstream = static_cast<std::size_t>(4.5 * cells);
  const std::size_t n = upstream + static_cast<std::size_t>(1.5 * cells) + 1;
  const Grid grid = Grid::line(n, dx, Boundary::free);
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
    gap[i] = x * x / (2.0 * radius);
  }
  FlowConditions conditions;
  conditions.viscosity = eta0;
  const double u = 1e-11 * e_prime * radius / eta0;
  conditions.entrainment_velocity = {u, 0.0};
  const LubricantLaws laws{.piezoviscosity = Piezoviscosity::roelands,
                           .pressure_viscosity = 5000.0 / e_prime,
                           .compressibility = Compressibility::dowson_higginson};
  FftInfluenceOperator op(grid, e_star);
  const ElasticFilm film = solve_elastic_film(op, gap, conditions, laws, {.load = load});
  ASSERT_TRUE(film.converged()) << film.message;

  const FilmShear rolling = film_shear(grid, conditions, laws, {}, film.film, film.pressure, film.fluid_fraction);
  EXPECT_EQ(rolling.couette_force[0], 0.0);
  // Pure rolling: the Poiseuille traction, (1/2) int p h' dx, is of order h/b of the load.
  EXPECT_LT(std::abs(rolling.friction_coefficient), 10.0 * film.central_film_thickness / b);

  // The traction curve: the Couette traction rises with the sliding speed
  // towards the plateau gamma (Evans & Johnson 1986) and never exceeds the
  // cap's integral, gamma W + tau_L0 L.
  const double gamma = 0.05;
  const ShearLimits cap{.limiting_shear_stress = 1.0, .limiting_shear_slope = gamma};
  const double length = static_cast<double>(n - 1) * dx;
  double previous = 0.0;
  for (const double ratio : {0.5, 2.0, 20.0, 50.0}) {
    conditions.sliding_velocity = {ratio * u, 0.0};
    const FilmShear sliding = film_shear(grid, conditions, laws, cap, film.film, film.pressure, film.fluid_fraction);
    const FilmShear newtonian = film_shear(grid, conditions, laws, {}, film.film, film.pressure, film.fluid_fraction);
    const double couette = sliding.couette_force[0] / sliding.load;
    std::printf("EHL traction at du/u = %g: Couette %.6g (gamma %.3g), total %.6g, Newtonian %.3g, limited %.3g\n",
                ratio, couette, gamma, sliding.friction_coefficient, newtonian.friction_coefficient,
                sliding.limited_fraction);
    EXPECT_GT(couette, previous);
    EXPECT_LE(sliding.couette_force[0], gamma * sliding.load + 1.0 * length);
    EXPECT_LT(sliding.friction_coefficient, newtonian.friction_coefficient);
    // The Poiseuille part is the rolling one, whatever the sliding.
    EXPECT_NEAR(sliding.friction_force[0] - sliding.couette_force[0], rolling.friction_force[0], 1e-12 * sliding.load);
    previous = couette;
  }
  EXPECT_GT(previous, 0.97 * gamma);  // at du = 50 u the cap holds wherever p > 0
}

TEST(FilmShearTest, RejectsInvalidLimits) {
  const auto message = [](const ShearLimits& limits) {
    try {
      limits.validate();
    } catch (const OptionError& e) {
      return e.option() + ": " + e.what();
    }
    return std::string("no error");
  };
  EXPECT_NE(message({.eyring_stress = -1.0}).find("eyring_stress"), std::string::npos);
  EXPECT_NE(message({.limiting_shear_stress = NAN}).find("limiting_shear_stress"), std::string::npos);
  EXPECT_NE(message({.limiting_shear_slope = -0.05}).find("limiting_shear_slope = -0.05 is invalid"),
            std::string::npos);
  EXPECT_EQ(message({.limiting_shear_slope = 0.05}), "no error");  // tau_L = gamma p
  EXPECT_EQ(message({.eyring_stress = 1e6, .limiting_shear_stress = 1e7, .limiting_shear_slope = 0.05}), "no error");
}

}  // namespace
}  // namespace halfspace::lubrication
