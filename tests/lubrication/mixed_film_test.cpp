// Mixed lubrication on a rough line contact: the thick-film limit equals the
// EHL solver, the thin-film limit the dry contact solver on the same rough
// gap, the load balance and both complementarities hold when checked apart
// from the solver, separation control reproduces load control, and the
// Stribeck curve passes from full film through mixed to boundary
// lubrication.
#include "halfspace/lubrication/mixed_film.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/cavitation_solver.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/fft_influence_operator.hpp"
#include "halfspace/solvers/polonsky_keer.hpp"
#include "support/analytic_solutions.hpp"
#include "support/outlet_touching_wedge.hpp"

namespace halfspace::lubrication {
namespace {

constexpr double kEStar = 1.1e11;    // Pa
constexpr double kRadius = 0.01;     // m
constexpr double kViscosity = 0.04;  // Pa s
constexpr double kLoad = 4.4e4;      // N/m: W = 2e-5
constexpr double kAlpha = 5000.0 / (2.0 * kEStar);

// A cylinder with transverse roughness: three incommensurate waves of
// `amplitude` (m) in all, their wavelengths a fraction of the Hertz width.
struct RoughLine {
  Grid grid;
  Eigen::ArrayXd gap;
  double half_width;
};

RoughLine rough_line(double amplitude, double cells_per_half_width = 24.0) {
  const testing::HertzLine hertz = testing::hertz_line(kLoad, kRadius, kEStar);
  const double dx = hertz.half_width / cells_per_half_width;
  const auto upstream = static_cast<std::size_t>(std::lround(3.0 * cells_per_half_width));
  const auto n = upstream + static_cast<std::size_t>(std::lround(1.5 * cells_per_half_width)) + 1;
  Eigen::ArrayXd gap(static_cast<Eigen::Index>(n));
  const double b = hertz.half_width;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (static_cast<double>(i) - static_cast<double>(upstream)) * dx;
    const double roughness =
        amplitude / 3.0 *
        (std::sin(2.0 * std::numbers::pi * x / (0.37 * b)) + std::sin(2.0 * std::numbers::pi * x / (0.61 * b) + 1.0) +
         std::sin(2.0 * std::numbers::pi * x / (0.23 * b) + 2.0));
    gap[static_cast<Eigen::Index>(i)] = x * x / (2.0 * kRadius) + roughness;
  }
  gap -= gap.minCoeff();
  return {Grid::line(n, dx, Boundary::free), gap, b};
}

FlowConditions flow(double speed, double slide_to_roll = 0.5) {
  FlowConditions c;
  c.viscosity = kViscosity;
  c.entrainment_velocity = {speed, 0.0};
  c.sliding_velocity = {slide_to_roll * speed, 0.0};
  return c;
}

LubricantLaws laws() {
  LubricantLaws l;
  l.piezoviscosity = Piezoviscosity::roelands;
  l.pressure_viscosity = kAlpha;
  l.compressibility = Compressibility::dowson_higginson;
  return l;
}

MixedFilmOptions mixed_options(double load = kLoad) {
  MixedFilmOptions options;
  options.load = load;
  options.friction.contact_friction = 0.1;
  options.friction.shear.limiting_shear_slope = 0.05;
  return options;
}

// The conditions checked apart from the solver: the film rebuilt from the
// pressures with the operator's own product, the load, h >= 0 and p_c >= 0
// and p_c h = 0, the fluid's p–theta complementarity, and the flux-form mass
// balance on h_R = reynolds_film(h, h_b).
void expect_solution_holds(FftInfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                           const MixedFilmOptions& options, const MixedFilm& f) {
  const std::size_t n = op.grid().size();
  Eigen::ArrayXd total = f.fluid_pressure + f.contact_pressure;
  Eigen::ArrayXd deformation(static_cast<Eigen::Index>(n));
  op.apply({total.data(), n}, {deformation.data(), n});
  const Eigen::ArrayXd film = f.offset + gap + deformation;
  const double film_scale = 1e-7;  // m: well above the rounding of h0 + g + K p (h0 ~ 1e-4 m here)
  EXPECT_GE(film.minCoeff(), -1e-9 * film_scale);
  EXPECT_GE(f.contact_pressure.minCoeff(), 0.0);
  EXPECT_GE(f.fluid_pressure.minCoeff(), 0.0);
  for (Eigen::Index k = 0; k < film.size(); ++k) {
    if (f.contact_pressure[k] > 0.0) {
      EXPECT_LE(std::abs(film[k]), 1e-9 * film_scale) << "cell " << k;
    }
  }
  if (options.load_controlled()) {
    EXPECT_NEAR(total.sum() * op.grid().cell_area() / options.load, 1.0, 1e-8);
  }
  EXPECT_TRUE(satisfies_complementarity(f.fluid_pressure, f.fluid_fraction));
  EXPECT_LE(elastic_film_residual(op.grid(), conditions, laws(), reynolds_film(film, options.boundary_film),
                                  f.fluid_pressure, f.fluid_fraction),
            10.0 * options.tolerance);
  EXPECT_NEAR(f.contact_load_fraction, f.contact_pressure.sum() / total.sum(), 1e-12);
}

// The film the Reynolds equation sees: the gap above 1.5 h_b, h_b below h_b / 2,
// within h_b / 8 of max(h, h_b) and never below it, with a slope that is
// the difference quotient's and continuous at both joins (no kink for the
// Newton iteration to stall on).
TEST(MixedFilmTest, ReynoldsFilmRoundsTheBoundaryFilmOff) {
  const double hb = 2e-9;
  EXPECT_EQ(reynolds_film(3.0 * hb, hb), 3.0 * hb);
  EXPECT_EQ(reynolds_film(1.5 * hb, hb), 1.5 * hb);
  EXPECT_EQ(reynolds_film(0.0, hb), hb);
  EXPECT_EQ(reynolds_film(-hb, hb), hb);
  EXPECT_DOUBLE_EQ(reynolds_film(hb, hb), 1.125 * hb);
  const double step = 1e-6 * hb;
  for (double h = 0.3 * hb; h <= 1.7 * hb; h += 0.01 * hb) {
    const double r = reynolds_film(h, hb);
    EXPECT_GE(r, std::max(h, hb) * (1.0 - 1e-15)) << h / hb;
    EXPECT_LE(r - std::max(h, hb), 0.125 * hb * (1.0 + 1e-12)) << h / hb;
    const double quotient = (reynolds_film(h + step, hb) - reynolds_film(h - step, hb)) / (2.0 * step);
    EXPECT_NEAR(reynolds_film_slope(h, hb), quotient, 1e-6) << h / hb;
  }
  for (const double join : {0.5 * hb, 1.5 * hb}) {
    EXPECT_NEAR(reynolds_film_slope(join - step, hb), reynolds_film_slope(join + step, hb), 2e-6) << join / hb;
  }
}

// Thick film: no cell comes near closing, the contact pressure is 0 and the
// film is the EHL solver's, to the EHL solver's tolerance.
TEST(MixedFilmTest, ThickFilmEqualsTheElasticFilm) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  for (const double speed : {10.0, 1.0}) {
    SCOPED_TRACE(::testing::Message() << "speed " << speed);
    const FlowConditions conditions = flow(speed);
    const MixedFilm mixed = solve_mixed_film(op, line.gap, conditions, laws(), mixed_options());
    const ElasticFilm ehl = solve_elastic_film(op, line.gap, conditions, laws(), {.load = kLoad});
    ASSERT_TRUE(mixed.converged()) << mixed.message;
    ASSERT_TRUE(ehl.converged()) << ehl.message;
    EXPECT_EQ(mixed.contact_load_fraction, 0.0);
    EXPECT_EQ(mixed.contact_area_fraction, 0.0);
    // With no cell below h_b the two Newton iterations solve the same
    // equations from the same start, on paths that differ where the mixed
    // film's stops nodes at the cavitation switch: measured equal to 3e-10
    // (pressure, of the peak; film, of the thinnest), asserted well below
    // the solvers' tolerance of 1e-8.
    const double peak = ehl.pressure.maxCoeff();
    EXPECT_LE((mixed.pressure - ehl.pressure).abs().maxCoeff(), 2e-9 * peak);
    EXPECT_LE((mixed.film - ehl.film).abs().maxCoeff(), 2e-9 * ehl.minimum_film_thickness);
    EXPECT_NEAR(mixed.central_film_thickness / ehl.central_film_thickness, 1.0, 2e-9);
    EXPECT_NEAR(mixed.minimum_film_thickness / ehl.minimum_film_thickness, 1.0, 2e-9);
    expect_solution_holds(op, line.gap, conditions, mixed_options(), mixed);
  }
}

// Thin film: as the speed falls the fluid's share vanishes and the pressure
// tends to the dry contact's on the same rough gap at the same load
// (Polonsky–Keer, the contact solvers' own), the difference falling with
// the speed.
TEST(MixedFilmTest, SlowFilmTendsToTheDryContact) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  solvers::PolonskyKeer dry_solver(op);
  const solvers::SolveResult dry =
      dry_solver.solve({line.gap.data(), line.grid.size()}, solvers::Loading::force(kLoad));
  ASSERT_TRUE(dry.converged());
  std::vector<double> differences, fluid_shares;
  const MixedFilm* previous = nullptr;
  std::vector<MixedFilm> films;
  films.reserve(3);
  for (const double speed : {1e-3, 3e-4, 1e-4}) {
    SCOPED_TRACE(::testing::Message() << "speed " << speed);
    films.push_back(solve_mixed_film(op, line.gap, flow(speed), laws(), mixed_options(), previous));
    const MixedFilm& f = films.back();
    ASSERT_TRUE(f.converged()) << f.message;
    expect_solution_holds(op, line.gap, flow(speed), mixed_options(), f);
    differences.push_back((f.pressure - dry.pressure).abs().maxCoeff() / dry.max_pressure);
    fluid_shares.push_back(1.0 - f.contact_load_fraction);
    previous = &f;
  }
  // Measured (109 nodes): differences 0.045, 0.0096, 0.0041 of the dry
  // peak; the fluid's share 0.079, 0.020, 0.0058, about proportional to the
  // speed; 12 cells in contact against the dry contact's 13 (the edge cell
  // of one patch, whose dry pressure is small, carried by fluid instead).
  EXPECT_LT(differences[2], 0.01);
  EXPECT_LT(differences[1], 0.5 * differences[0]);
  EXPECT_LT(differences[2], 0.6 * differences[1]);
  EXPECT_LT(fluid_shares[2], 0.01);
  EXPECT_LT(fluid_shares[1], 0.5 * fluid_shares[0]);
  EXPECT_LT(fluid_shares[2], 0.5 * fluid_shares[1]);
  EXPECT_NEAR(films.back().contact_area_fraction, dry.contact_fraction, 2.0 / static_cast<double>(line.grid.size()));
}

// Separation control at the offset load control found carries the same load
// with the same pressures: from a film at another speed, and cold (from the
// load-controlled film at the dry contact's load, continued in h0). Both
// solved to a mass residual of 1e-11: the pressures of two films that meet
// the default 1e-8 differ by up to 9e-8 of the peak (measured), as the
// residual allows.
TEST(MixedFilmTest, SeparationControlReproducesLoadControl) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  const FlowConditions conditions = flow(0.0215);
  MixedFilmOptions load_options = mixed_options();
  load_options.tolerance = 1e-11;
  const MixedFilm by_load = solve_mixed_film(op, line.gap, conditions, laws(), load_options);
  ASSERT_TRUE(by_load.converged()) << by_load.message;
  ASSERT_GT(by_load.contact_load_fraction, 0.1);
  ASSERT_LT(by_load.contact_load_fraction, 0.9);
  MixedFilmOptions options = mixed_options(0.0);
  options.tolerance = 1e-11;
  options.offset = by_load.offset;
  const MixedFilm other_speed = solve_mixed_film(op, line.gap, flow(0.01), laws(), mixed_options());
  ASSERT_TRUE(other_speed.converged()) << other_speed.message;
  for (const MixedFilm* start : {&other_speed, static_cast<const MixedFilm*>(nullptr)}) {
    SCOPED_TRACE(start != nullptr ? "from the film at 0.01 m/s" : "cold");
    const MixedFilm by_offset = solve_mixed_film(op, line.gap, conditions, laws(), options, start);
    ASSERT_TRUE(by_offset.converged()) << by_offset.message;
    expect_solution_holds(op, line.gap, conditions, options, by_offset);
    // Measured: pressures within 7e-12 of the peak.
    EXPECT_NEAR(by_offset.load / kLoad, 1.0, 1e-8);
    EXPECT_LE((by_offset.pressure - by_load.pressure).abs().maxCoeff(), 1e-8 * by_load.max_pressure);
  }
}

// The Stribeck curve of the rough line: boundary lubrication at the lowest
// speeds (the contact carries nearly all the load, the friction coefficient
// is Coulomb's), mixed lubrication in between, a full film above, where the
// friction coefficient falls to a minimum and then rises with the speed
// (the film's shear).
TEST(MixedFilmTest, StribeckCurveHasItsThreeRegimes) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  const std::vector<double> speeds{10.0, 3.0, 1.0, 0.3, 0.1, 0.03, 0.01, 1e-3, 1e-4};
  const std::vector<StribeckPoint> curve = stribeck_sweep(op, line.gap, flow(1.0), laws(), mixed_options(), speeds);
  ASSERT_EQ(curve.size(), speeds.size());
  for (const StribeckPoint& point : curve) {
    SCOPED_TRACE(::testing::Message() << "speed " << point.entrainment_speed);
    ASSERT_TRUE(point.film.converged()) << point.film.message;
    EXPECT_NEAR(point.hersey_number, kViscosity * point.entrainment_speed / kLoad, 1e-15);
  }
  for (std::size_t k = 1; k < curve.size(); ++k) {
    EXPECT_GE(curve[k].film.contact_load_fraction, curve[k - 1].film.contact_load_fraction);
  }
  // Full film at 0.1 m/s and above, mixed at 0.03 and 0.01, boundary below.
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(curve[k].film.contact_load_fraction, 0.0);
  EXPECT_GT(curve[5].film.contact_load_fraction, 0.05);
  EXPECT_LT(curve[6].film.contact_load_fraction, 0.9);
  EXPECT_GT(curve[8].film.contact_load_fraction, 0.99);
  EXPECT_NEAR(curve[8].film.friction_coefficient, 0.1, 0.002);
  // The friction minimum lies in the full film, below both ends.
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < curve.size(); ++k) {
    if (curve[k].film.friction_coefficient < curve[lowest].film.friction_coefficient) lowest = k;
  }
  EXPECT_GT(lowest, 0u);
  EXPECT_LT(lowest, 5u);
  EXPECT_LT(curve[lowest].film.friction_coefficient, 0.5 * curve[8].film.friction_coefficient);
  EXPECT_LT(curve[lowest].film.friction_coefficient, curve[0].film.friction_coefficient);
}

// The shared sweep's runs: every speed once, contiguous runs in speed order
// on the processes from the last to the first (the last speed on process
// 0), their lengths within one of each other.
TEST(MixedFilmTest, StribeckRunsCoverTheSpeedsOnceTheLastOnTheFirstProcess) {
  for (std::size_t speeds = 0; speeds <= 11; ++speeds) {
    for (int size = 1; size <= 5; ++size) {
      SCOPED_TRACE(::testing::Message() << speeds << " speeds on " << size << " processes");
      std::size_t next = 0, shortest = speeds, longest = 0;
      for (int rank = size - 1; rank >= 0; --rank) {
        const auto [first, end] = stribeck_run(speeds, rank, size);
        EXPECT_EQ(first, next);
        ASSERT_GE(end, first);
        next = end;
        shortest = std::min(shortest, end - first);
        longest = std::max(longest, end - first);
      }
      EXPECT_EQ(next, speeds);
      EXPECT_LE(longest - shortest, 1u);
      if (speeds > 0) {
        EXPECT_EQ(stribeck_run(speeds, 0, size).second, speeds);
      }
    }
  }
}

// On one process the shared sweep is the sweep, to the bit.
TEST(MixedFilmTest, SharedSweepOnOneProcessIsTheSweep) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  const std::vector<double> speeds{0.1, 0.03};
  const std::vector<StribeckPoint> plain = stribeck_sweep(op, line.gap, flow(1.0), laws(), mixed_options(), speeds);
  const std::vector<StribeckPoint> shared =
      stribeck_sweep(op, line.gap, flow(1.0), laws(), mixed_options(), speeds, linalg::serial_communicator());
  ASSERT_EQ(shared.size(), plain.size());
  for (std::size_t k = 0; k < plain.size(); ++k) {
    ASSERT_TRUE(plain[k].film.converged()) << plain[k].film.message;
    EXPECT_EQ(shared[k].hersey_number, plain[k].hersey_number);
    EXPECT_TRUE((shared[k].film.pressure == plain[k].film.pressure).all());
    EXPECT_EQ(shared[k].film.friction_coefficient, plain[k].film.friction_coefficient);
  }
}

// A wedge that touches only at its outlet edge, where the pressure is
// imposed: the dry contact that starts the Newton iteration carries the
// load on that node alone. Nearly rigid the film is the inclined slider's,
// on a softer body it is the EHL
// film's (ElasticFilmTest.WedgeTouchingAtItsOutletEdgeIsTheInclinedSlider).
TEST(MixedFilmTest, WedgeTouchingAtItsOutletEdgeIsTheInclinedSlider) {
  const testing::OutletTouchingWedge wedge;
  const Grid& grid = wedge.grid;
  const Eigen::ArrayXd& gap = wedge.gap;
  const FlowConditions& conditions = wedge.conditions;
  const LubricantLaws rigid_laws{.piezoviscosity = Piezoviscosity::none, .compressibility = Compressibility::none};
  MixedFilmOptions options = mixed_options(100.0);
  options.couette_scheme = CouetteScheme::second_order;
  FftInfluenceOperator stiff(grid, 1e15);
  const MixedFilm rigid = solve_mixed_film(stiff, gap, conditions, rigid_laws, options);
  ASSERT_TRUE(rigid.converged()) << rigid.message;
  EXPECT_EQ(rigid.contact_load_fraction, 0.0);
  EXPECT_NEAR(wedge.slider_load(rigid.film) / options.load, 1.0, 1e-3);

  FftInfluenceOperator steel(grid, 1e11);
  const LubricantLaws compressible{.compressibility = Compressibility::dowson_higginson};
  const MixedFilm mixed = solve_mixed_film(steel, gap, conditions, compressible, mixed_options(1e3));
  const ElasticFilm ehl = solve_elastic_film(steel, gap, conditions, compressible, {.load = 1e3});
  ASSERT_TRUE(mixed.converged()) << mixed.message;
  ASSERT_TRUE(ehl.converged()) << ehl.message;
  EXPECT_EQ(mixed.contact_load_fraction, 0.0);
  EXPECT_LE(mixed.relative_residual, 1e-7);
  EXPECT_LE(mixed.load_error, 1e-7);
  EXPECT_TRUE(satisfies_complementarity(mixed.fluid_pressure, mixed.fluid_fraction));
  EXPECT_NEAR(mixed.minimum_film_thickness / ehl.minimum_film_thickness, 1.0, 1e-6);
}

TEST(MixedFilmTest, RefusesInvalidOptionsNamingThem) {
  const RoughLine line = rough_line(0.2e-6);
  FftInfluenceOperator op(line.grid, kEStar);
  const auto message = [&](MixedFilmOptions options, FlowConditions conditions = flow(1.0)) {
    try {
      (void)solve_mixed_film(op, line.gap, conditions, laws(), options);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  MixedFilmOptions options = mixed_options();
  options.boundary_film = 0.0;
  EXPECT_NE(message(options).find("boundary_film = 0 m"), std::string::npos);
  options = mixed_options();
  options.friction.contact_friction = -0.1;
  EXPECT_NE(message(options).find("contact_friction"), std::string::npos);
  options = mixed_options();
  options.friction.shear.limiting_shear_slope = std::nan("");
  EXPECT_NE(message(options).find("limiting_shear_slope"), std::string::npos);
  options = mixed_options();
  options.load = -1.0;
  EXPECT_NE(message(options).find("load"), std::string::npos);
  options = mixed_options();
  options.contact_tolerance = 2.0;
  EXPECT_NE(message(options).find("contact_tolerance = 2"), std::string::npos);
  EXPECT_NE(message(mixed_options(), flow(0.0)).find("entrainment velocity is zero"), std::string::npos);
  // Beyond the dense path's node limit, when the dense path is asked for
  // (the automatic choice takes GMRES there: mixed_film_krylov_test.cpp).
  const Grid big = Grid::line(kMaxMixedFilmNodes + 1, 1e-6, Boundary::free);
  FftInfluenceOperator big_op(big, kEStar);
  const Eigen::ArrayXd flat = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(big.size()));
  MixedFilmOptions dense = mixed_options();
  dense.linear_solve = FilmLinearSolve::dense;
  try {
    (void)solve_mixed_film(big_op, flat, flow(1.0), laws(), dense);
    ADD_FAILURE() << "no error beyond the node limit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 2048"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)stribeck_sweep(op, line.gap, flow(1.0), laws(), mixed_options(), {1.0, -2.0}), InputError);
}

}  // namespace
}  // namespace halfspace::lubrication
