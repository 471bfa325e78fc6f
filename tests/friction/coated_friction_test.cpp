// Friction on a coated half-space (ElasticPair::coated): a
// layer of the substrate's own material is the homogeneous body; a layer much
// thicker than the domain is the layer's material alone; a thin stiff layer
// stiffens the contact tangentially, and its stick/slip step agrees with an
// independent dense solve (the compliance matrix summed mode by mode from the
// symbols, no FFT; the step by projected Gauss-Seidel on the discs).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "friction/friction_checks.hpp"
#include "halfspace/error.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/frictional_solve.hpp"
#include "halfspace/solvers/tangential_solver.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace {
namespace {

const ElasticBody kSteel{2.1e11, 0.3};
const ElasticBody kCeramic{4.2e11, 0.22};  // a stiffer layer
constexpr double kRadius = 0.01;           // m
constexpr double kForce = 5.0;             // N
constexpr double kMu = 0.3;

// A sphere pressed into an n x n periodic grid four Hertz radii (of `pair`'s
// E*) wide; the tangential history is `steps`.
struct SphereCase {
  Grid grid;
  Eigen::ArrayXd heights;
};

SphereCase periodic_sphere(double e_star, std::size_t n) {
  const double a = testing::hertz_point(kForce, kRadius, e_star).radius;
  const double h = 4.0 * a / static_cast<double>(n);
  const Grid grid = Grid::plane(n, n, h, h, Boundary::periodic);
  return {grid, testing::field_from(grid, [](double x, double y) { return -(x * x + y * y) / (2 * kRadius); })};
}

FrictionalSolveResult solve(const SphereCase& sphere, const ElasticPair& pair, const FrictionOptions& friction) {
  return solvers::solve_frictional_surface(sphere.grid, {sphere.heights.data(), sphere.grid.size()}, pair,
                                           Loading::force(kForce),
                                           testing::test_options(solvers::SolverType::pk_fourier, 1e-12), friction);
}

FrictionOptions history(bool coupling) {
  FrictionOptions friction;
  friction.tangential.friction_coefficient = kMu;
  friction.history = {TangentialLoading::force(0.5 * kMu * kForce), TangentialLoading::force(0.8 * kMu * kForce, 0.2),
                      TangentialLoading::force(0.2 * kMu * kForce)};
  friction.tangential.tolerance = 1e-12;
  friction.coupled_step.tolerance = 1e-12;
  friction.coupling = coupling;
  return friction;
}

// The largest difference of the shear, the stick map and the approach of
// two histories, relative to mu p_max and the approach.
struct HistoryDifference {
  double shear = 0.0;
  double approach = 0.0;
  double pressure = 0.0;
  long stick_changes = 0;
};

HistoryDifference compare(const FrictionalSolveResult& a, const FrictionalSolveResult& b) {
  HistoryDifference d;
  const double p_max = a.normal.pressure.maxCoeff();
  d.pressure = (a.normal.pressure - b.normal.pressure).abs().maxCoeff() / p_max;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    const TangentialState& s = a.steps[k].state;
    const TangentialState& t = b.steps[k].state;
    d.shear = std::max({d.shear, (s.shear_x - t.shear_x).abs().maxCoeff() / (kMu * p_max),
                        (s.shear_y - t.shear_y).abs().maxCoeff() / (kMu * p_max)});
    d.approach = std::max(d.approach, std::hypot(s.approach_x - t.approach_x, s.approach_y - t.approach_y) /
                                          std::hypot(s.approach_x, s.approach_y));
    d.stick_changes += (a.steps[k].stick != b.steps[k].stick).count();
  }
  return d;
}

// The kernel of a layer of the substrate's own material is the homogeneous
// body's to rounding, mode by mode, for every q t.
TEST(CoatedFriction, OneMaterialLayerHasTheHomogeneousSymbols) {
  constexpr double kSymbolTolerance = 1e-12;  // two small solves in double precision
  const ElasticPair homogeneous = ElasticPair::on_rigid(kSteel);
  const ElasticPair coated = ElasticPair::coated({1e-6, kSteel, kSteel});
  double worst = 0.0;
  for (const double qt : {1e-3, 0.1, 1.0, 3.0, 10.0, 100.0}) {
    const double q = qt / 1e-6;
    const double qx = 0.6 * q;
    const double qy = 0.8 * q;
    const kernels::TangentialCoefficients a = homogeneous.tangential_symbol(qx, qy);
    const kernels::TangentialCoefficients b = coated.tangential_symbol(qx, qy);
    const kernels::CouplingCoefficients c = homogeneous.coupling_symbol(qx, qy);
    const kernels::CouplingCoefficients e = coated.coupling_symbol(qx, qy);
    const double scale = a.xx;
    worst = std::max({worst, std::abs(a.xx - b.xx) / scale, std::abs(a.yy - b.yy) / scale,
                      std::abs(a.xy - b.xy) / scale, std::abs(c.x - e.x) / scale, std::abs(c.y - e.y) / scale});
  }
  std::printf("one-material layer: largest symbol difference %.3g of the xx symbol\n", worst);
  EXPECT_LT(worst, kSymbolTolerance);
  EXPECT_FALSE(coated.similar());  // as the homogeneous body on a rigid one: beta = (1 - 2 nu)/(2 (1 - nu))
  EXPECT_EQ(coated.dundurs_beta(), homogeneous.dundurs_beta());
  EXPECT_TRUE(ElasticPair::coated({1e-6, {kSteel.youngs_modulus, 0.5}, {kSteel.youngs_modulus, 0.5}}).similar());
}

// (a) The whole history of a coated body whose layer is the substrate's
// material equals the homogeneous body's, coupled and uncoupled.
TEST(CoatedFriction, OneMaterialLayerGivesTheHomogeneousHistory) {
  // The symbols agree to 1e-13; the solves, each to 1e-12, carry it through.
  constexpr double kTolerance = 1e-10;
  const ElasticPair homogeneous = ElasticPair::on_rigid(kSteel);
  const ElasticPair coated = ElasticPair::coated({2e-5, kSteel, kSteel});
  const SphereCase sphere = periodic_sphere(homogeneous.composite_modulus(), 48);
  for (const bool coupling : {false, true}) {
    SCOPED_TRACE(coupling ? "coupled" : "uncoupled");
    const FrictionalSolveResult a = solve(sphere, homogeneous, history(coupling));
    const FrictionalSolveResult b = solve(sphere, coated, history(coupling));
    ASSERT_TRUE(a.converged()) << a.failure();
    ASSERT_TRUE(b.converged()) << b.failure();
    EXPECT_EQ(b.coupled, coupling);
    const HistoryDifference d = compare(a, b);
    std::printf("%s: pressure %.3g, shear %.3g of mu p_max, approach %.3g, %ld stick cells differ\n",
                coupling ? "coupled" : "uncoupled", d.pressure, d.shear, d.approach, d.stick_changes);
    EXPECT_LT(d.pressure, kTolerance);
    EXPECT_LT(d.shear, kTolerance);
    EXPECT_LT(d.approach, kTolerance);
    EXPECT_EQ(d.stick_changes, 0);
  }
}

// (b) A layer three times as thick as the domain is wide: every mode but
// the mean decays within it (the slowest, q t = 6 pi, feels the substrate
// by about (2 q t)^2 exp(-2 q t) ~ 6e-14 of its compliance), so the
// substrate (five times stiffer here) is not felt and the answer is the
// homogeneous layer material's. (At twice the width the
// trace, 8e-9, showed as 7e-9 in the shear.)
TEST(CoatedFriction, ThickLayerGivesTheLayerMaterialsHistory) {
  constexpr double kTolerance = 1e-10;  // the substrate's trace above, amplified by the solves
  const ElasticPair layer = ElasticPair::on_rigid(kSteel);
  const SphereCase sphere = periodic_sphere(layer.composite_modulus(), 48);
  const double width = static_cast<double>(sphere.grid.nx()) * sphere.grid.dx();
  const ElasticPair coated = ElasticPair::coated({3.0 * width, kSteel, {5.0 * kSteel.youngs_modulus, 0.25}});
  for (const bool coupling : {false, true}) {
    SCOPED_TRACE(coupling ? "coupled" : "uncoupled");
    const FrictionalSolveResult a = solve(sphere, layer, history(coupling));
    const FrictionalSolveResult b = solve(sphere, coated, history(coupling));
    ASSERT_TRUE(a.converged()) << a.failure();
    ASSERT_TRUE(b.converged()) << b.failure();
    const HistoryDifference d = compare(a, b);
    std::printf("thick layer, %s: pressure %.3g, shear %.3g of mu p_max, approach %.3g, %ld stick cells differ\n",
                coupling ? "coupled" : "uncoupled", d.pressure, d.shear, d.approach, d.stick_changes);
    EXPECT_LT(d.pressure, kTolerance);
    EXPECT_LT(d.shear, kTolerance);
    EXPECT_LT(d.approach, kTolerance);
    EXPECT_EQ(d.stick_changes, 0);
  }
}

// The dense reference on a small periodic grid (odd sides: no Nyquist mode,
// whose odd parts a real transform cannot carry). The compliance matrix of
// the traction (x then y per cell) summed mode by mode from the pair's
// symbol, C(i, j) = (1/N) sum_q S(q) cos(q.(x_i - x_j)) (S is even in q),
// and the coupling's K_a(i, j) = -(1/N) sum_q c_a(q) sin(q.(x_i - x_j)).
struct DenseCompliance {
  Eigen::MatrixXd tangential;  // 2N x 2N
  Eigen::MatrixXd coupling;    // 2N x N: the tangential displacement of a pressure
};

DenseCompliance dense_compliance(const Grid& grid, const ElasticPair& pair) {
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const auto n = static_cast<Eigen::Index>(grid.size());
  DenseCompliance d{Eigen::MatrixXd::Zero(2 * n, 2 * n), Eigen::MatrixXd::Zero(2 * n, n)};
  // The kernel per offset (di, dj), then laid out by cell pairs.
  Eigen::ArrayXXd xx = Eigen::ArrayXXd::Zero(static_cast<Eigen::Index>(ny), static_cast<Eigen::Index>(nx));
  Eigen::ArrayXXd yy = xx, xy = xx, cx = xx, cy = xx;
  for (std::size_t r = 0; r < ny; ++r) {
    for (std::size_t c = 0; c < nx; ++c) {
      const double qx = kernels::dft_wavenumber(c, nx, grid.dx());
      const double qy = kernels::dft_wavenumber(r, ny, grid.dy());
      kernels::TangentialCoefficients s;
      kernels::CouplingCoefficients odd;
      pair.symbols(qx, qy, s, odd);
      for (std::size_t dj = 0; dj < ny; ++dj) {
        for (std::size_t di = 0; di < nx; ++di) {
          const double phase = qx * static_cast<double>(di) * grid.dx() + qy * static_cast<double>(dj) * grid.dy();
          const auto j = static_cast<Eigen::Index>(dj);
          const auto i = static_cast<Eigen::Index>(di);
          xx(j, i) += s.xx * std::cos(phase);
          yy(j, i) += s.yy * std::cos(phase);
          xy(j, i) += s.xy * std::cos(phase);
          cx(j, i) -= odd.x * std::sin(phase);
          cy(j, i) -= odd.y * std::sin(phase);
        }
      }
    }
  }
  const double inverse_n = 1.0 / static_cast<double>(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index b = 0; b < n; ++b) {
      const auto ai = static_cast<std::size_t>(a);
      const auto bi = static_cast<std::size_t>(b);
      const auto i = static_cast<Eigen::Index>((ai % nx + nx - bi % nx) % nx);
      const auto j = static_cast<Eigen::Index>((ai / nx + ny - bi / nx) % ny);
      d.tangential(2 * a, 2 * b) = xx(j, i) * inverse_n;
      d.tangential(2 * a + 1, 2 * b + 1) = yy(j, i) * inverse_n;
      d.tangential(2 * a, 2 * b + 1) = xy(j, i) * inverse_n;
      d.tangential(2 * a + 1, 2 * b) = xy(j, i) * inverse_n;
      d.coupling(2 * a, b) = cx(j, i) * inverse_n;
      d.coupling(2 * a + 1, b) = cy(j, i) * inverse_n;
    }
  }
  return d;
}

// One displacement-controlled step from rest under the pressure p: the
// minimiser of 1/2 q.C q - delta . sum_i q_i over the discs |q_i| <= mu p_i,
// by block Gauss-Seidel (each cell's 2x2 block is c I on a square grid, so
// the projected block step is the block's exact minimiser) until no
// traction moves by 1e-14 of mu p_max.
Eigen::VectorXd dense_stick_slip(const Eigen::MatrixXd& c, const Eigen::ArrayXd& pressure, double delta_x,
                                 double delta_y, bool& converged) {
  const Eigen::Index n = pressure.size();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2 * n);
  const double limit = kMu * pressure.maxCoeff();
  converged = false;
  for (int sweep = 0; sweep < 200000 && !converged; ++sweep) {
    double moved = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double diagonal = c(2 * i, 2 * i);
      const double gx = c.row(2 * i).dot(q) - delta_x;
      const double gy = c.row(2 * i + 1).dot(q) - delta_y;
      double x = q[2 * i] - gx / diagonal;
      double y = q[2 * i + 1] - gy / diagonal;
      const double radius = kMu * pressure[i];
      const double size = std::hypot(x, y);
      if (size > radius) {
        x *= radius / size;
        y *= radius / size;
      }
      moved = std::max({moved, std::abs(x - q[2 * i]), std::abs(y - q[2 * i + 1])});
      q[2 * i] = x;
      q[2 * i + 1] = y;
    }
    converged = moved <= 1e-14 * limit;
  }
  return q;
}

// A Hertzian pressure of radius a (m) and peak p0 (Pa) at the grid's centre.
Eigen::ArrayXd hertz_pressure(const Grid& grid, double a, double p0) {
  return testing::field_from(grid, [&](double x, double y) {
    const double r2 = (x * x + y * y) / (a * a);
    return r2 < 1.0 ? p0 * std::sqrt(1.0 - r2) : 0.0;
  });
}

// (c) A thin stiff layer (t = a/4, E twice the substrate's): the operator's
// products equal the dense matrices; its stick/slip step equals the dense
// projected Gauss-Seidel one; and under the same pressure and tangential
// force the tangential approach lies between the substrate's and the layer
// material's (stiffer than the substrate, softer than the layer alone).
TEST(CoatedFriction, ThinStiffLayerAgreesWithADenseSolveAndStiffensTheContact) {
  constexpr double kProductTolerance = 1e-12;  // an FFT against a direct sum, both in double
  constexpr double kStepTolerance = 1e-8;      // of mu p_max: two solvers, each converged far below it
  const std::size_t n = 15;
  const double a = 1e-4;
  const double h = 4.0 * a / static_cast<double>(n);
  const Grid grid = Grid::plane(n, n, h, h, Boundary::periodic);
  const ElasticPair coated = ElasticPair::coated({0.25 * a, kCeramic, kSteel});
  const Eigen::ArrayXd pressure = hertz_pressure(grid, 1.1 * a, 1e9);
  const DenseCompliance dense = dense_compliance(grid, coated);
  TangentialOperator op(grid, coated);
  ASSERT_TRUE(op.coupled());

  // The products, on a pseudo-random traction.
  const auto cells = static_cast<Eigen::Index>(grid.size());
  const Eigen::ArrayXd tx = Eigen::ArrayXd::Random(cells);
  const Eigen::ArrayXd ty = Eigen::ArrayXd::Random(cells);
  Eigen::ArrayXd ux(cells), uy(cells), vx(cells), vy(cells);
  op.apply({tx.data(), grid.size()}, {ty.data(), grid.size()}, {ux.data(), grid.size()}, {uy.data(), grid.size()});
  op.apply_pressure_coupling({pressure.data(), grid.size()}, {vx.data(), grid.size()}, {vy.data(), grid.size()});
  Eigen::VectorXd t(2 * cells);
  for (Eigen::Index i = 0; i < cells; ++i) {
    t[2 * i] = tx[i];
    t[2 * i + 1] = ty[i];
  }
  const Eigen::VectorXd u = dense.tangential * t;
  const Eigen::VectorXd v = dense.coupling * pressure.matrix();
  double product = 0.0;
  double coupling = 0.0;
  for (Eigen::Index i = 0; i < cells; ++i) {
    product = std::max({product, std::abs(ux[i] - u[2 * i]), std::abs(uy[i] - u[2 * i + 1])});
    coupling = std::max({coupling, std::abs(vx[i] - v[2 * i]), std::abs(vy[i] - v[2 * i + 1])});
  }
  product /= u.cwiseAbs().maxCoeff();
  coupling /= v.cwiseAbs().maxCoeff();
  std::printf("thin stiff layer: products against the dense sums %.3g (tangential), %.3g (coupling)\n", product,
              coupling);
  EXPECT_LT(product, kProductTolerance);
  EXPECT_LT(coupling, kProductTolerance);

  // One step from rest, the shear partly slipping, along a skew direction.
  const double delta_x = 4e-8;
  const double delta_y = 1.5e-8;
  TangentialOptions options;
  options.friction_coefficient = kMu;
  options.tolerance = 1e-13;
  TangentialSolver solver(op, options);
  const TangentialResult step =
      solver.solve({pressure.data(), grid.size()}, TangentialLoading::displacement(delta_x, delta_y),
                   TangentialState::unloaded(grid.size()));
  ASSERT_TRUE(step.converged()) << step.message;
  bool converged = false;
  const Eigen::VectorXd q = dense_stick_slip(dense.tangential, pressure, delta_x, delta_y, converged);
  ASSERT_TRUE(converged);
  double worst = 0.0;
  long slipping = 0;
  for (Eigen::Index i = 0; i < cells; ++i) {
    worst =
        std::max({worst, std::abs(step.state.shear_x[i] - q[2 * i]), std::abs(step.state.shear_y[i] - q[2 * i + 1])});
    if (pressure[i] > 0.0 && step.stick[i] != 1.0) ++slipping;
  }
  worst /= kMu * pressure.maxCoeff();
  std::printf(
      "thin stiff layer: shear against dense Gauss-Seidel %.3g of mu p_max; stick fraction %.3f, %ld cells "
      "slip\n",
      worst, step.stick_fraction, slipping);
  EXPECT_LT(worst, kStepTolerance);
  EXPECT_GT(slipping, 0);             // partial slip: the test reaches the circle
  EXPECT_GT(step.stick_fraction, 0);  // and the stick zone

  // The tangential approach under the same pressure and force: the coated
  // body between its substrate and its layer material.
  const double force = 0.5 * kMu * pressure.sum() * grid.cell_area();
  auto approach = [&](const ElasticPair& pair) {
    TangentialOperator other(grid, pair);
    TangentialSolver s(other, options);
    const TangentialResult r = s.solve({pressure.data(), grid.size()}, TangentialLoading::force(force),
                                       TangentialState::unloaded(grid.size()));
    EXPECT_TRUE(r.converged()) << r.message;
    return r.state.approach_x;
  };
  const double substrate = approach(ElasticPair::on_rigid(kSteel));
  const double layered = approach(coated);
  const double layer = approach(ElasticPair::on_rigid(kCeramic));
  std::printf("tangential approach at Q = mu P/2: substrate %.4g m, coated %.4g m, layer material %.4g m\n", substrate,
              layered, layer);
  EXPECT_LT(layered, substrate);
  EXPECT_GT(layered, layer);
}

// (d) Free grids: a sphere on a thin stiff layer (t = a/4), one step to
// Q = mu P/2 (partial slip). Coupled and uncoupled, the shear balances Q,
// the pressure P and Coulomb's bound holds in every cell; uncoupled, the
// stick and slip conditions hold when checked apart from the solver (a
// fresh product of the returned shear), and the free 32^2 grid (4 a wide)
// agrees with a periodic 96^2 one (12 a) with the same cells near the
// contact within twice the difference of the homogeneous substrate in the
// same two grids (the periodic images and the two discretisations, not the
// coated free kernel, set it).
TEST(CoatedFriction, FreeGridSphereIsSaneAndAgreesWithALargePeriodicGrid) {
  constexpr std::size_t kFree = 32;
  constexpr std::size_t kPeriodic = 96;
  const ElasticPair substrate = ElasticPair::on_rigid(kSteel);
  const double a = testing::hertz_point(kForce, kRadius, substrate.composite_modulus()).radius;
  const double h = 4.0 * a / static_cast<double>(kFree);
  const ElasticPair coated = ElasticPair::coated({0.25 * a, kCeramic, kSteel});
  auto sphere = [&](std::size_t n, Boundary boundary) {
    const Grid grid = Grid::plane(n, n, h, h, boundary);
    return SphereCase{grid,
                      testing::field_from(grid, [](double x, double y) { return -(x * x + y * y) / (2 * kRadius); })};
  };
  const SphereCase free = sphere(kFree, Boundary::free);
  const SphereCase periodic = sphere(kPeriodic, Boundary::periodic);
  auto one_step = [](bool coupling) {
    FrictionOptions friction = history(coupling);
    friction.history = {TangentialLoading::force(0.5 * kMu * kForce)};
    return friction;
  };
  // The largest differences of pressure and shear (of p_max, mu p_max) over
  // the free grid's cells, and the stick cells that differ.
  auto compare_window = [&](const FrictionalSolveResult& f, const FrictionalSolveResult& g) {
    const std::size_t shift = (kPeriodic - kFree) / 2;
    const double p_max = f.normal.pressure.maxCoeff();
    const TangentialResult& s = f.steps.back();
    const TangentialResult& t = g.steps.back();
    HistoryDifference d;
    for (std::size_t j = 0; j < kFree; ++j) {
      for (std::size_t i = 0; i < kFree; ++i) {
        const auto k = static_cast<Eigen::Index>(j * kFree + i);
        const auto m = static_cast<Eigen::Index>((j + shift) * kPeriodic + i + shift);
        d.pressure = std::max(d.pressure, std::abs(f.normal.pressure[k] - g.normal.pressure[m]) / p_max);
        d.shear = std::max({d.shear, std::abs(s.state.shear_x[k] - t.state.shear_x[m]) / (kMu * p_max),
                            std::abs(s.state.shear_y[k] - t.state.shear_y[m]) / (kMu * p_max)});
        d.stick_changes += s.stick[k] != t.stick[m] ? 1 : 0;
      }
    }
    return d;
  };
  for (const bool coupling : {false, true}) {
    SCOPED_TRACE(coupling ? "coupled" : "uncoupled");
    const FrictionalSolveResult f = solve(free, coated, one_step(coupling));
    ASSERT_TRUE(f.converged()) << f.failure();
    EXPECT_EQ(f.coupled, coupling);
    const TangentialResult& step = f.steps.back();
    const Eigen::ArrayXd& pressure = coupling ? f.step_normals.back().pressure : f.normal.pressure;
    const double area = free.grid.cell_area();
    EXPECT_NEAR(step.state.shear_x.sum() * area, 0.5 * kMu * kForce, 1e-9 * kMu * kForce);
    EXPECT_NEAR(step.state.shear_y.sum() * area, 0.0, 1e-9 * kMu * kForce);
    EXPECT_NEAR(pressure.sum() * area, kForce, 1e-9 * kForce);
    EXPECT_LE(((step.state.shear_x.square() + step.state.shear_y.square()).sqrt() - kMu * pressure).maxCoeff(),
              1e-12 * kMu * pressure.maxCoeff());
    std::printf("free coated sphere, %s: stick fraction %.3f\n", coupling ? "coupled" : "uncoupled",
                step.stick_fraction);
    EXPECT_GT(step.stick_fraction, 0.1);  // partial slip
    EXPECT_LT(step.stick_fraction, 0.9);
    if (coupling) continue;
    TangentialOperator op(free.grid, coated);
    testing::expect_coulomb_conditions(op, f.normal.pressure, kMu, TangentialState::unloaded(free.grid.size()), step,
                                       1e-6 * std::abs(step.state.approach_x), 1e-3);
    // Periodic against free, and the homogeneous substrate's same difference.
    const FrictionalSolveResult g = solve(periodic, coated, one_step(false));
    ASSERT_TRUE(g.converged()) << g.failure();
    const HistoryDifference d = compare_window(f, g);
    const HistoryDifference e =
        compare_window(solve(free, substrate, one_step(false)), solve(periodic, substrate, one_step(false)));
    std::printf(
        "periodic against free: pressure %.3g of p_max, shear %.3g of mu p_max, %ld stick cells differ "
        "(homogeneous substrate: %.3g, %.3g, %ld)\n",
        d.pressure, d.shear, d.stick_changes, e.pressure, e.shear, e.stick_changes);
    EXPECT_LT(d.pressure, 2.0 * e.pressure);
    EXPECT_LT(d.shear, 2.0 * e.shear);
  }
}

// Where the remainder cannot go in by DFT (a layer not thin against the
// domain, a line) friction is refused, naming the coating and why.
TEST(CoatedFriction, ThickLayersOnFreeGridsAreRefused) {
  const ElasticPair coated = ElasticPair::coated({2e-6, kCeramic, kSteel});
  const Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free);
  try {
    FrictionOptions::check_body(grid, coated);
    ADD_FAILURE() << "a thick coating on a small free grid was accepted";
  } catch (const solvers::SolverOptionError& error) {
    EXPECT_EQ(error.option(), "coating");
    EXPECT_NE(std::string(error.what()).find("1/8 of the shorter side"), std::string::npos) << error.what();
  }
  EXPECT_NO_THROW(FrictionOptions::check_body(Grid::plane(32, 32, 1e-6, 1e-6, Boundary::free), coated));
}

}  // namespace
}  // namespace halfspace
