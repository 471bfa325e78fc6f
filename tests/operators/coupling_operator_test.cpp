// The normal-tangential coupling of dissimilar bodies in TangentialOperator:
// the FFT products against the dense sums of the closed-form coefficients
// (free grids, to rounding), the two products each other's transposes
// (Betti), a periodic mode against the symbol, the periodic symbol against
// the free operator near a small patch, the signs against Boussinesq's and
// Cerruti's point-load displacements, and nothing at all for similar bodies.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>

#include "halfspace/kernels/coupling_fourier.hpp"
#include "halfspace/kernels/coupling_rectangle.hpp"
#include "halfspace/kernels/coupling_strip.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "support/grid_fields.hpp"

namespace halfspace {
namespace {

// Steel on aluminium: beta = 0.036 (the aluminium is body 2).
const ElasticPair kPair({2.1e11, 0.3}, {7e10, 0.33});

Eigen::ArrayXd random_field(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  Eigen::ArrayXd f(static_cast<Eigen::Index>(n));
  for (auto& v : f) v = value(rng);
  return f;
}

kernels::CouplingCoefficients coefficient(const Grid& grid, double x, double y) {
  const double d = kPair.coupling_compliance();
  return grid.dimension() == 1 ? kernels::coupling_strip_displacement(x, grid.dx(), d)
                               : kernels::coupling_rectangle_displacement(x, y, 0.5 * grid.dx(), 0.5 * grid.dy(), d);
}

void expect_equals_dense_products(const Grid& grid) {
  TangentialOperator op(grid, kPair);
  ASSERT_TRUE(op.coupled());
  const std::size_t n = grid.size();
  const Eigen::ArrayXd p = random_field(n, 1).abs();
  const Eigen::ArrayXd tx = random_field(n, 2);
  const Eigen::ArrayXd ty =
      grid.dimension() == 1 ? Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n)).eval() : random_field(n, 3);
  Eigen::ArrayXd vx(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd vy(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd w(static_cast<Eigen::Index>(n));
  op.apply_pressure_coupling({p.data(), n}, {vx.data(), n}, {vy.data(), n});
  op.apply_traction_coupling({tx.data(), n}, {ty.data(), n}, {w.data(), n});
  double largest_v = 0.0;
  double largest_w = 0.0;
  double worst_v = 0.0;
  double worst_w = 0.0;
  for (std::size_t j = 0; j < grid.ny(); ++j) {
    for (std::size_t i = 0; i < grid.nx(); ++i) {
      double sx = 0.0;
      double sy = 0.0;
      double sw = 0.0;
      for (std::size_t l = 0; l < grid.ny(); ++l) {
        for (std::size_t k = 0; k < grid.nx(); ++k) {
          const double x = (static_cast<double>(i) - static_cast<double>(k)) * grid.dx();
          const double y = (static_cast<double>(j) - static_cast<double>(l)) * grid.dy();
          const kernels::CouplingCoefficients c = coefficient(grid, x, y);
          const auto s = static_cast<Eigen::Index>(l * grid.nx() + k);
          sx += c.x * p[s];
          sy += c.y * p[s];
          sw -= c.x * tx[s] + c.y * ty[s];  // the transpose: the odd kernel's negative
        }
      }
      const auto t = static_cast<Eigen::Index>(j * grid.nx() + i);
      largest_v = std::max({largest_v, std::abs(sx), std::abs(sy)});
      largest_w = std::max(largest_w, std::abs(sw));
      worst_v = std::max({worst_v, std::abs(vx[t] - sx), std::abs(vy[t] - sy)});
      worst_w = std::max(worst_w, std::abs(w[t] - sw));
    }
  }
  EXPECT_GT(largest_v, 0.0);
  EXPECT_LE(worst_v, 1e-12 * largest_v) << grid.shape_string();
  EXPECT_LE(worst_w, 1e-12 * largest_w) << grid.shape_string();
}

TEST(CouplingOperator, FreeProductsEqualTheDenseSumsToRounding) {
  expect_equals_dense_products(Grid::plane(9, 7, 1e-6, 1.5e-6, Boundary::free));
  expect_equals_dense_products(Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free));
  expect_equals_dense_products(Grid::line(17, 1e-6, Boundary::free));
}

// p . (K^T t) = t . (K p) on every grid kind: the 3x3 compliance is symmetric.
TEST(CouplingOperator, TheTwoProductsAreEachOthersTransposes) {
  for (const Grid& grid :
       {Grid::plane(24, 20, 1e-6, 1.5e-6, Boundary::free), Grid::line(40, 1e-6, Boundary::free),
        Grid::plane(32, 16, 1e-6, 2e-6, Boundary::periodic), Grid::line(64, 1e-6, Boundary::periodic)}) {
    TangentialOperator op(grid, kPair);
    const std::size_t n = grid.size();
    const Eigen::ArrayXd p = random_field(n, 4);
    const Eigen::ArrayXd tx = random_field(n, 5);
    const Eigen::ArrayXd ty =
        grid.dimension() == 1 ? Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n)).eval() : random_field(n, 6);
    Eigen::ArrayXd vx(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd vy(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd w(static_cast<Eigen::Index>(n));
    op.apply_pressure_coupling({p.data(), n}, {vx.data(), n}, {vy.data(), n});
    op.apply_traction_coupling({tx.data(), n}, {ty.data(), n}, {w.data(), n});
    const double t_v = (tx * vx + ty * vy).sum();
    const double p_w = (p * w).sum();
    const double scale = std::sqrt((tx * tx + ty * ty).sum() * (vx * vx + vy * vy).sum());
    EXPECT_NEAR(p_w, t_v, 1e-12 * scale) << grid.shape_string();
    EXPECT_GT(std::abs(t_v), 1e-3 * scale) << grid.shape_string();
  }
}

// A pressure mode cos(q.x) moves the surfaces tangentially by -c sin(q.x)
// (U = i c P with c odd in q), a traction mode cos(q.x) t normally by
// c.t sin(q.x).
TEST(CouplingOperator, PeriodicModeIsMultipliedByTheSymbol) {
  // ky = -2: a row past the stored half of the ky-folded symbol, where c_y
  // takes the stored value's negative (odd ny too).
  for (const Grid& grid :
       {Grid::plane(32, 16, 1e-6, 2e-6, Boundary::periodic), Grid::plane(12, 9, 1e-6, 1.5e-6, Boundary::periodic),
        Grid::line(64, 1e-6, Boundary::periodic)}) {
    TangentialOperator op(grid, kPair);
    const double qx = 2.0 * std::numbers::pi * 3.0 / (static_cast<double>(grid.nx()) * grid.dx());
    const double qy =
        grid.dimension() == 1 ? 0.0 : 2.0 * std::numbers::pi * -2.0 / (static_cast<double>(grid.ny()) * grid.dy());
    const std::size_t n = grid.size();
    Eigen::ArrayXd p(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd sine(static_cast<Eigen::Index>(n));
    for (std::size_t j = 0; j < grid.ny(); ++j) {
      for (std::size_t i = 0; i < grid.nx(); ++i) {
        const double phase = qx * static_cast<double>(i) * grid.dx() + qy * static_cast<double>(j) * grid.dy();
        p[static_cast<Eigen::Index>(j * grid.nx() + i)] = 2e6 * std::cos(phase);
        sine[static_cast<Eigen::Index>(j * grid.nx() + i)] = 2e6 * std::sin(phase);
      }
    }
    const Eigen::ArrayXd ty = -0.5 * p;
    Eigen::ArrayXd vx(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd vy(static_cast<Eigen::Index>(n));
    Eigen::ArrayXd w(static_cast<Eigen::Index>(n));
    op.apply_pressure_coupling({p.data(), n}, {vx.data(), n}, {vy.data(), n});
    op.apply_traction_coupling({p.data(), n}, {ty.data(), n}, {w.data(), n});
    const kernels::CouplingCoefficients c = kernels::coupling_spectrum(qx, qy, kPair.coupling_compliance());
    const double tolerance = 1e-12 * 2e6 * std::hypot(c.x, c.y);
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      EXPECT_NEAR(vx[i], -c.x * sine[i], tolerance);
      EXPECT_NEAR(vy[i], -c.y * sine[i], tolerance);
      EXPECT_NEAR(w[i], (c.x - 0.5 * c.y) * sine[i], tolerance);
    }
  }
}

// The signs and the size against the point-load solutions (Johnson 1985),
// written here for an elastic body 1 (G, nu) on a rigid body 2 without
// ElasticPair's factors: a pressure force P at the origin pulls body 1's
// surface radially inwards by (1 - 2 nu) P/(4 pi G r) (Boussinesq, eq.
// 3.21a), so body 2's surface moves outwards relative to it; a tangential
// force F_x on body 2 (-F_x on body 1) lifts body 1's surface ahead of it
// out of body 1 by... in body 1's frame (1 - 2 nu)(-F_x) x/(4 pi G r^2)
// into body 1 (Cerruti, eq. 3.86c), i.e. its surface moves towards body 2
// and the gap closes: u_n = -(1 - 2 nu) F_x x/(4 pi G r^2). A cell far
// away acts as its point force to O((h/r)^2).
TEST(CouplingOperator, SignsFollowBoussinesqAndCerruti) {
  const double e = 2e11;
  const double nu = 0.25;
  const double g = e / (2.0 * (1.0 + nu));
  const ElasticPair pair = ElasticPair::on_rigid({e, nu});
  const double h = 1e-6;
  const double area = h * h;
  const double factor = (1.0 - 2.0 * nu) / (4.0 * std::numbers::pi * g);
  for (const auto& [x, y] : {std::pair{20e-6, 0.0}, std::pair{-12e-6, 16e-6}, std::pair{7e-6, -24e-6}}) {
    const double r2 = x * x + y * y;
    const kernels::CouplingCoefficients c =
        kernels::coupling_rectangle_displacement(x, y, 0.5 * h, 0.5 * h, pair.coupling_compliance());
    // Boussinesq: body 1's surface displacement is -factor P x_a/r^2; the relative one its negative.
    EXPECT_NEAR(c.x, factor * area * x / r2, 2e-3 * factor * area / std::sqrt(r2));
    EXPECT_NEAR(c.y, factor * area * y / r2, 2e-3 * factor * area / std::sqrt(r2));
    // Cerruti: u_n = -factor F_a x_a/r^2, and the operator's is -c_a per unit traction.
    EXPECT_NEAR(-c.x, -factor * area * x / r2, 2e-3 * factor * area / std::sqrt(r2));
  }
  // Plane strain (Flamant, Johnson eq. 2.19b): a normal line load P pulls
  // the surface towards it by (1 - 2 nu) P/(4 G) on either side.
  const kernels::CouplingCoefficients strip =
      kernels::coupling_strip_displacement(5e-6, 1e-6, pair.coupling_compliance());
  EXPECT_NEAR(strip.x, (1.0 - 2.0 * nu) / (4.0 * g) * 1e-6, 1e-15 * strip.x);
  EXPECT_EQ(kernels::coupling_strip_displacement(0.0, 1e-6, pair.coupling_compliance()).x, 0.0);
  EXPECT_EQ(kernels::coupling_rectangle_displacement(0.0, 3e-6, 0.5e-6, 0.5e-6, 1.0).x, 0.0);
}

// Near a small patch on a periodic grid and on a free grid of the same cells
// the displacement differences from the patch centre agree once the
// periodic images are allowed for. The kernel is (D/(4 pi)) d/dx_a ln(rho),
// and the mean-free periodic sum of ln(rho) has the Laplacian 2 pi (delta -
// 1/A) (A the cell of periodicity): near the origin it is ln(rho) -
// pi rho^2/(2 A) + O(rho^4/A^2) (square lattice), so the images add the
// linear field -(D/(4 A)) x_a per unit force, 2.8 % of the kernel at 24
// cells on 256^2 (the tangential kernel's images only add curvature).
TEST(CouplingOperator, PeriodicSymbolAgreesWithTheFreeKernelNearASmallPatch) {
  const std::size_t n = 256;
  const double h = 1e-6;
  const Grid periodic = Grid::plane(n, n, h, h, Boundary::periodic);
  const Grid free = Grid::plane(n, n, h, h, Boundary::free);
  const double radius = 16.0 * h;
  auto bump = [&](double x, double y) {
    const double r2 = (x * x + y * y) / (radius * radius);
    return r2 < 1.0 ? 1e6 * (1.0 - r2) * (1.0 - r2) : 0.0;
  };
  const Eigen::ArrayXd p = testing::field_from(free, bump);
  const Eigen::ArrayXd tx = 0.5 * p;
  const Eigen::ArrayXd ty = -0.25 * p;
  const std::size_t m = n * n;
  Eigen::ArrayXd fx(static_cast<Eigen::Index>(m)), fy(static_cast<Eigen::Index>(m)), fw(static_cast<Eigen::Index>(m));
  Eigen::ArrayXd px(static_cast<Eigen::Index>(m)), py(static_cast<Eigen::Index>(m)), pw(static_cast<Eigen::Index>(m));
  TangentialOperator free_op(free, kPair);
  TangentialOperator periodic_op(periodic, kPair);
  free_op.apply_pressure_coupling({p.data(), m}, {fx.data(), m}, {fy.data(), m});
  free_op.apply_traction_coupling({tx.data(), m}, {ty.data(), m}, {fw.data(), m});
  periodic_op.apply_pressure_coupling({p.data(), m}, {px.data(), m}, {py.data(), m});
  periodic_op.apply_traction_coupling({tx.data(), m}, {ty.data(), m}, {pw.data(), m});
  // The images' linear field per unit force and unit distance.
  const double image = kPair.coupling_compliance() / (4.0 * periodic.domain_area());
  const double force = p.sum() * h * h;
  const auto centre = static_cast<Eigen::Index>((n / 2) * n + n / 2);
  double largest = 0.0;
  double worst = 0.0;
  double worst_without_images = 0.0;
  for (std::size_t j = n / 2 - 24; j <= n / 2 + 24; ++j) {
    for (std::size_t i = n / 2 - 24; i <= n / 2 + 24; ++i) {
      const auto k = static_cast<Eigen::Index>(j * n + i);
      const double x = (static_cast<double>(i) - static_cast<double>(n / 2)) * h;
      const double y = (static_cast<double>(j) - static_cast<double>(n / 2)) * h;
      const double dx = (fx[k] - fx[centre]) - (px[k] - px[centre]);
      const double dy = (fy[k] - fy[centre]) - (py[k] - py[centre]);
      const double dw = (fw[k] - fw[centre]) - (pw[k] - pw[centre]);
      largest = std::max({largest, std::abs(fx[k] - fx[centre]), std::abs(fw[k] - fw[centre])});
      worst_without_images = std::max({worst_without_images, std::abs(dx), std::abs(dw)});
      worst = std::max({worst, std::abs(dx - image * force * x), std::abs(dy - image * force * y),
                        std::abs(dw + image * force * (0.5 * x - 0.25 * y))});
    }
  }
  std::printf(
      "coupling, periodic against free near the patch: %.2e of the largest difference (%.2e without the "
      "images' linear field)\n",
      worst / largest, worst_without_images / largest);
  EXPECT_LE(worst, 5e-3 * largest);                 // the discretisations differ (point symbol, cell coefficients)
  EXPECT_GT(worst_without_images, 1e-2 * largest);  // the images' field is really there
}

TEST(CouplingOperator, SimilarBodiesDoNotCouple) {
  const Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free);
  TangentialOperator op(grid, ElasticPair::similar({2.1e11, 0.3}));
  EXPECT_FALSE(op.coupled());
  const Eigen::ArrayXd p = random_field(grid.size(), 7);
  Eigen::ArrayXd vx = p;
  Eigen::ArrayXd vy = p;
  op.apply_pressure_coupling({p.data(), grid.size()}, {vx.data(), grid.size()}, {vy.data(), grid.size()});
  EXPECT_EQ(vx.abs().maxCoeff(), 0.0);
  EXPECT_EQ(vy.abs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace halfspace
