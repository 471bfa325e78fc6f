// The tangential operator: the FFT product against the dense sum of the
// kernels' coefficients (free grids, to rounding), a single periodic mode
// against the symbol, and the periodic symbol against the free operator for
// a small traction patch (the periodic images change little near it).
#include "halfspace/operators/tangential_operator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>

#include "halfspace/kernels/cerruti_rectangle.hpp"
#include "halfspace/kernels/tangential_fourier.hpp"
#include "halfspace/kernels/tangential_strip.hpp"
#include "support/grid_fields.hpp"

namespace halfspace {
namespace {

const ElasticPair kPair({2.1e11, 0.3}, {7e10, 0.33});

Eigen::ArrayXd random_field(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  Eigen::ArrayXd f(static_cast<Eigen::Index>(n));
  for (auto& v : f) v = value(rng);
  return f;
}

void expect_equals_dense_product(const Grid& grid) {
  TangentialOperator op(grid, kPair);
  const std::size_t n = grid.size();
  const Eigen::ArrayXd tx = random_field(n, 1);
  const Eigen::ArrayXd ty = random_field(n, 2);
  Eigen::ArrayXd ux(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd uy(static_cast<Eigen::Index>(n));
  op.apply({tx.data(), n}, {ty.data(), n}, {ux.data(), n}, {uy.data(), n});
  const double a = 0.5 * grid.dx();
  const double b = 0.5 * grid.dy();
  double largest = 0.0;
  double worst = 0.0;
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      double sx = 0.0;
      double sy = 0.0;
      for (std::size_t l = 0; l < grid.ny(); ++l) {
        for (std::size_t k = 0; k < grid.nx(); ++k) {
          const double x = (static_cast<double>(i) - static_cast<double>(k)) * grid.dx();
          const double y = (static_cast<double>(j) - static_cast<double>(l)) * grid.dy();
          const kernels::TangentialCoefficients c =
              grid.dimension() == 1 ? kernels::tangential_strip_displacement(x, grid.dx(), kPair.composite_modulus(),
                                                                             kPair.shear_compliance())
                                    : kernels::cerruti_rectangle_displacement(x, y, a, b, kPair.shear_compliance(),
                                                                              kPair.directional_compliance());
          const std::size_t s = l * grid.nx() + k;
          sx += c.xx * tx[static_cast<Eigen::Index>(s)] + c.xy * ty[static_cast<Eigen::Index>(s)];
          sy += c.xy * tx[static_cast<Eigen::Index>(s)] + c.yy * ty[static_cast<Eigen::Index>(s)];
        }
      }
      const auto t = static_cast<Eigen::Index>(j * grid.nx() + i);
      largest = std::max({largest, std::abs(sx), std::abs(sy)});
      worst = std::max({worst, std::abs(ux[t] - sx), std::abs(uy[t] - sy)});
    }
  }
  EXPECT_LE(worst, 1e-12 * largest) << grid.shape_string();
}

TEST(TangentialOperator, FreeProductEqualsTheDenseSumToRounding) {
  expect_equals_dense_product(Grid::plane(9, 7, 1e-6, 1.5e-6, Boundary::free));
  expect_equals_dense_product(Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free));
  expect_equals_dense_product(Grid::line(17, 1e-6, Boundary::free));
}

TEST(TangentialOperator, FreeSelfInfluenceIsTheCellsOwnCoefficient) {
  const Grid grid = Grid::plane(6, 5, 1e-6, 2e-6, Boundary::free);
  TangentialOperator op(grid, kPair);
  const kernels::TangentialCoefficients c = kernels::cerruti_rectangle_displacement(
      0.0, 0.0, 0.5e-6, 1e-6, kPair.shear_compliance(), kPair.directional_compliance());
  EXPECT_EQ(op.self_influence().xx, c.xx);
  EXPECT_EQ(op.self_influence().yy, c.yy);
}

TEST(TangentialOperator, PeriodicModeIsMultipliedByTheSymbol) {
  // ky = -2: a row past the stored half of the ky-folded symbol, where xy
  // takes the stored value's negative (odd ny too).
  for (const Grid& grid :
       {Grid::plane(32, 16, 1e-6, 2e-6, Boundary::periodic), Grid::plane(12, 9, 1e-6, 1.5e-6, Boundary::periodic)}) {
    TangentialOperator op(grid, kPair);
    const double qx = 2.0 * std::numbers::pi * 3.0 / (static_cast<double>(grid.nx()) * grid.dx());
    const double qy = 2.0 * std::numbers::pi * -2.0 / (static_cast<double>(grid.ny()) * grid.dy());
    const std::size_t n = grid.size();
    Eigen::ArrayXd tx(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd ty(static_cast<Eigen::Index>(n));
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      for (std::size_t i = 0; i < grid.nx(); ++i) {
        const double phase = qx * static_cast<double>(i) * grid.dx() + qy * static_cast<double>(j) * grid.dy();
        tx[static_cast<Eigen::Index>(j * grid.nx() + i)] = 2e6 * std::cos(phase);
        ty[static_cast<Eigen::Index>(j * grid.nx() + i)] = -1e6 * std::cos(phase);
      }
    }
    Eigen::ArrayXd ux = tx;
    Eigen::ArrayXd uy = ty;
    op.apply({ux.data(), n}, {uy.data(), n}, {ux.data(), n}, {uy.data(), n});  // in place
    const kernels::TangentialCoefficients s =
        kernels::tangential_spectrum(qx, qy, kPair.shear_compliance(), kPair.directional_compliance());
    EXPECT_NE(s.xy, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      EXPECT_NEAR(ux[i], s.xx * tx[i] + s.xy * ty[i], 1e-12 * 2e6 * s.xx);
      EXPECT_NEAR(uy[i], s.xy * tx[i] + s.yy * ty[i], 1e-12 * 2e6 * s.xx);
    }
  }
}

// The preconditioner: on a periodic grid the exact inverse of C apart from
// the mean mode (C's null space, where M keeps the largest eigenvalue's
// inverse), so M C t returns t less its mean (t made of modes below the
// Nyquist frequencies, where the odd xy part of a real field's symbol is
// lost); on a free grid only an approximate inverse, symmetric and positive
// definite: t . M u = u . M t and t . M t > 0.
TEST(TangentialOperator, ApproximateInverseInvertsThePeriodicSymbol) {
  const Grid grid = Grid::plane(32, 16, 1e-6, 2e-6, Boundary::periodic);
  TangentialOperator op(grid, kPair);
  const std::size_t n = grid.size();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> amplitude(-1e6, 1e6);
  std::uniform_int_distribution<int> kx(-15, 15);
  std::uniform_int_distribution<int> ky(-7, 7);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  Eigen::ArrayXd tx = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), 3e5);
  Eigen::ArrayXd ty = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), -2e5);
  for (int mode = 0; mode < 12; ++mode) {
    const double qx = 2.0 * std::numbers::pi * kx(rng) / 32e-6;
    const double qy = 2.0 * std::numbers::pi * ky(rng) / 32e-6;
    const double ax = amplitude(rng);
    const double ay = amplitude(rng);
    const double shift = phase(rng);
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      for (std::size_t i = 0; i < grid.nx(); ++i) {
        const double angle = qx * static_cast<double>(i) * grid.dx() + qy * static_cast<double>(j) * grid.dy() + shift;
        tx[static_cast<Eigen::Index>(j * grid.nx() + i)] += ax * std::cos(angle);
        ty[static_cast<Eigen::Index>(j * grid.nx() + i)] += ay * std::cos(angle);
      }
    }
  }
  Eigen::ArrayXd ux(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd uy(static_cast<Eigen::Index>(n));
  op.apply({tx.data(), n}, {ty.data(), n}, {ux.data(), n}, {uy.data(), n});
  op.apply_approximate_inverse({ux.data(), n}, {uy.data(), n}, {ux.data(), n}, {uy.data(), n});  // in place
  const double largest = std::max(tx.abs().maxCoeff(), ty.abs().maxCoeff());
  EXPECT_LE((ux - (tx - tx.mean())).abs().maxCoeff(), 1e-12 * largest);
  EXPECT_LE((uy - (ty - ty.mean())).abs().maxCoeff(), 1e-12 * largest);
}

TEST(TangentialOperator, ApproximateInverseIsSymmetricPositiveOnFreeGrids) {
  for (const Grid& grid : {Grid::plane(24, 20, 1e-6, 1.5e-6, Boundary::free), Grid::line(40, 1e-6, Boundary::free)}) {
    TangentialOperator op(grid, kPair);
    const std::size_t n = grid.size();
    const Eigen::ArrayXd ax = random_field(n, 5);
    const Eigen::ArrayXd ay =
        grid.dimension() == 1 ? Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n)).eval() : random_field(n, 6);
    const Eigen::ArrayXd bx = random_field(n, 7);
    const Eigen::ArrayXd by =
        grid.dimension() == 1 ? Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n)).eval() : random_field(n, 8);
    Eigen::ArrayXd mx(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd my(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd nx(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd ny(static_cast<Eigen::Index>(n));
    op.apply_approximate_inverse({ax.data(), n}, {ay.data(), n}, {mx.data(), n}, {my.data(), n});
    op.apply_approximate_inverse({bx.data(), n}, {by.data(), n}, {nx.data(), n}, {ny.data(), n});
    const double b_m_a = (bx * mx + by * my).sum();
    const double a_m_b = (ax * nx + ay * ny).sum();
    EXPECT_NEAR(b_m_a, a_m_b, 1e-10 * std::abs(a_m_b)) << grid.shape_string();
    EXPECT_GT((ax * mx + ay * my).sum(), 0.0) << grid.shape_string();
    EXPECT_GT((bx * nx + by * ny).sum(), 0.0) << grid.shape_string();
  }
}

// A smooth traction patch (radius L/16) on a periodic grid of side L and on a
// free grid of the same cells: near the patch the periodic images add a
// nearly uniform field (the mean, removed), so the displacement differences
// from the centre agree to the images' curvature, ~(r/L)^3, and the two
// discretisations' difference.
TEST(TangentialOperator, PeriodicSymbolAgreesWithCerrutiNearASmallPatch) {
  const std::size_t n = 256;
  const double h = 1e-6;
  const Grid periodic = Grid::plane(n, n, h, h, Boundary::periodic);
  const Grid free = Grid::plane(n, n, h, h, Boundary::free);
  const double radius = 16.0 * h;
  auto bump = [&](double x, double y) {
    const double r2 = (x * x + y * y) / (radius * radius);
    return r2 < 1.0 ? 1e6 * (1.0 - r2) * (1.0 - r2) : 0.0;
  };
  const Eigen::ArrayXd tx = testing::field_from(free, bump);
  const Eigen::ArrayXd ty = 0.5 * tx;
  Eigen::ArrayXd fx(static_cast<Eigen::Index>(n * n));
  Eigen::ArrayXd fy(static_cast<Eigen::Index>(n * n));
  Eigen::ArrayXd px(static_cast<Eigen::Index>(n * n));
  Eigen::ArrayXd py(static_cast<Eigen::Index>(n * n));
  TangentialOperator(free, kPair).apply({tx.data(), n * n}, {ty.data(), n * n}, {fx.data(), n * n}, {fy.data(), n * n});
  TangentialOperator(periodic, kPair)
      .apply({tx.data(), n * n}, {ty.data(), n * n}, {px.data(), n * n}, {py.data(), n * n});
  const auto centre = static_cast<Eigen::Index>((n / 2) * n + n / 2);
  double largest = 0.0;
  double worst = 0.0;
  for (std::size_t j = n / 2 - 24; j <= n / 2 + 24; ++j) {
    for (std::size_t i = n / 2 - 24; i <= n / 2 + 24; ++i) {
      const auto k = static_cast<Eigen::Index>(j * n + i);
      largest = std::max(largest, std::abs(fx[k] - fx[centre]));
      worst = std::max({worst, std::abs((fx[k] - fx[centre]) - (px[k] - px[centre])),
                        std::abs((fy[k] - fy[centre]) - (py[k] - py[centre]))});
    }
  }
  std::printf("periodic against free near the patch: %.2e of the largest difference\n", worst / largest);
  EXPECT_LE(worst, 5e-3 * largest);
}

}  // namespace
}  // namespace halfspace
