// The tangential operator of a coated half-space on free grids (the layer's
// closed forms, the smoothed substrate-less-layer ones and the remainder per
// mode): against a periodic grid four times as wide with the same patch in
// its middle (an independent evaluation: the per-mode symbols only, no cell
// coefficients), and in the limits of one material (the homogeneous free
// operator, to rounding) and of a layer far thinner than a cell (the
// substrate's).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/kernels/cerruti_rectangle.hpp"
#include "halfspace/kernels/coupling_rectangle.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "support/grid_fields.hpp"

namespace halfspace {
namespace {

const ElasticBody kSteel{2.1e11, 0.3};
const ElasticBody kPolymer{7e10, 0.4};   // a softer layer
const ElasticBody kCeramic{4e11, 0.22};  // a stiffer one (E1*/E2* < 2: split height t)

// The four products of the operator on one set of fields.
struct Products {
  Eigen::ArrayXd ux, uy;  // C t
  Eigen::ArrayXd vx, vy;  // K p
  Eigen::ArrayXd w;       // K^T t
};

Products products(const Grid& grid, const ElasticPair& pair, const Eigen::ArrayXd& tx, const Eigen::ArrayXd& ty,
                  const Eigen::ArrayXd& p) {
  const std::size_t n = grid.size();
  const auto size = static_cast<Eigen::Index>(n);
  Products r{Eigen::ArrayXd(size), Eigen::ArrayXd(size), Eigen::ArrayXd(size), Eigen::ArrayXd(size),
             Eigen::ArrayXd(size)};
  TangentialOperator op(grid, pair);
  op.apply({tx.data(), n}, {ty.data(), n}, {r.ux.data(), n}, {r.uy.data(), n});
  op.apply_pressure_coupling({p.data(), n}, {r.vx.data(), n}, {r.vy.data(), n});
  op.apply_traction_coupling({tx.data(), n}, {ty.data(), n}, {r.w.data(), n});
  return r;
}

// A smooth traction and pressure patch of radius 8 cells at the centre.
struct Patch {
  Eigen::ArrayXd tx, ty, p;
};

Patch patch(const Grid& grid) {
  const double radius = 8.0 * grid.dx();
  auto bump = [&](double x, double y) {
    const double r2 = (x * x + y * y) / (radius * radius);
    return r2 < 1.0 ? 1e6 * (1.0 - r2) * (1.0 - r2) : 0.0;
  };
  const Eigen::ArrayXd base = testing::field_from(grid, bump);
  // An asymmetric shear (an x-gradient in t_y) so that xy and the odd parts count.
  const Eigen::ArrayXd ramp = testing::field_from(grid, [&](double x, double) { return 1.0 + x / radius; });
  return {base, 0.5 * base * ramp, 2.0 * base};
}

// The coating's effect, the products of the coated pair less those of the
// layer material alone, on the free grid and on the periodic one (whose
// middle it is): the largest difference over the free grid of each
// product's effect (its variation from the centre cell: the periodic mean
// mode is another datum), relative to that effect's largest variation.
// Taking the effect removes the difference of the two discretisations
// themselves (the periodic symbol sampled per mode, the free one integrated
// over cells: 1e-2 of the products near the patch for a homogeneous body,
// whatever the period).
double periodic_against_free(const ElasticPair& pair, const ElasticPair& layer, std::size_t n_free,
                             std::size_t n_periodic) {
  const double h = 1e-6;
  const Grid free = Grid::plane(n_free, n_free, h, h, Boundary::free);
  const Grid periodic = Grid::plane(n_periodic, n_periodic, h, h, Boundary::periodic);
  const Patch f = patch(free);
  const Patch g = patch(periodic);
  const Products a = products(free, pair, f.tx, f.ty, f.p);
  const Products a0 = products(free, layer, f.tx, f.ty, f.p);
  const Products b = products(periodic, pair, g.tx, g.ty, g.p);
  const Products b0 = products(periodic, layer, g.tx, g.ty, g.p);
  const std::size_t shift = (n_periodic - n_free) / 2;
  const auto centre_free = static_cast<Eigen::Index>((n_free / 2) * n_free + n_free / 2);
  const auto centre_periodic = static_cast<Eigen::Index>((n_periodic / 2) * n_periodic + n_periodic / 2);
  double worst = 0.0;
  const Eigen::ArrayXd Products::*fields[] = {&Products::ux, &Products::uy, &Products::vx, &Products::vy, &Products::w};
  for (const auto field : fields) {
    const Eigen::ArrayXd u = a.*field - a0.*field;
    const Eigen::ArrayXd v = b.*field - b0.*field;
    double largest = 0.0;
    double difference = 0.0;
    for (std::size_t j = 0; j < n_free; ++j) {
      for (std::size_t i = 0; i < n_free; ++i) {
        const auto k = static_cast<Eigen::Index>(j * n_free + i);
        const auto m = static_cast<Eigen::Index>((j + shift) * n_periodic + i + shift);
        const double du = u[k] - u[centre_free];
        largest = std::max(largest, std::abs(du));
        difference = std::max(difference, std::abs(du - (v[m] - v[centre_periodic])));
      }
    }
    worst = std::max(worst, difference / largest);
  }
  return worst;
}

// The free 64^2 grid against a periodic 512^2 one: the coating's effect on
// all five products. Measured: 1.8e-3 to 1.8e-2 of the effect (which is 3 to
// 30 % of the products). What remains is the periodic images for the thick
// soft layer (1.0e-2 on a 256^2 periodic grid, 1.8e-3 on 512^2) and the two
// discretisations' own difference for t = 2 dx (5.8e-3 on either); the
// thick stiff layer (t = L/8, the limit) also has the free remainder's
// folded images (1.8e-2; 3.2e-2 on 256^2).
TEST(CoatedTangentialOperator, FreeGridAgreesWithALargePeriodicOne) {
  constexpr double kTolerance = 2.5e-2;
  for (const auto& [layer, substrate] : {std::pair{kPolymer, kSteel}, std::pair{kCeramic, kSteel}}) {
    for (const double t : {2e-6, 8e-6}) {
      const double error =
          periodic_against_free(ElasticPair::coated({t, layer, substrate}), ElasticPair::on_rigid(layer), 64, 512);
      std::printf("E1 = %.3g Pa on E2 = %.3g Pa, t = %.3g m: periodic against free %.3g of the coating's effect\n",
                  layer.youngs_modulus, substrate.youngs_modulus, t, error);
      EXPECT_LT(error, kTolerance);
    }
  }
}

// The largest difference of each product of two pairs on one free grid,
// relative to the largest value of that product of the second pair.
double free_difference(const Grid& grid, const ElasticPair& a, const ElasticPair& b) {
  const Patch f = patch(grid);
  const Products u = products(grid, a, f.tx, f.ty, f.p);
  const Products v = products(grid, b, f.tx, f.ty, f.p);
  double worst = 0.0;
  const Eigen::ArrayXd Products::*fields[] = {&Products::ux, &Products::uy, &Products::vx, &Products::vy, &Products::w};
  for (const auto field : fields) {
    worst = std::max(worst, ((u.*field) - (v.*field)).abs().maxCoeff() / (v.*field).abs().maxCoeff());
  }
  return worst;
}

// A layer of the substrate's own material: the smoothed part and the
// remainder vanish, so the operator is the homogeneous one (Cerruti's and
// the coupling rectangles) to the rounding of the per-mode solves.
TEST(CoatedTangentialOperator, OneMaterialIsTheHomogeneousFreeOperator) {
  const Grid grid = Grid::plane(32, 32, 1e-6, 1e-6, Boundary::free);
  const double error =
      free_difference(grid, ElasticPair::coated({3e-6, kSteel, kSteel}), ElasticPair::on_rigid(kSteel));
  std::printf("one material: %.3g of the homogeneous products\n", error);
  EXPECT_LT(error, 1e-12);
}

// A layer a thousandth of a cell thick is the substrate to O(t/dx), and its
// closed-form part alone is already the substrate's Cerruti rectangle to
// that order: the remainder carries no cell-scale error.
TEST(CoatedTangentialOperator, ThinLayerIsTheSubstrate) {
  const Grid grid = Grid::plane(32, 32, 1e-6, 1e-6, Boundary::free);
  for (const ElasticBody& layer : {kPolymer, kCeramic}) {
    const double error =
        free_difference(grid, ElasticPair::coated({1e-9, layer, kSteel}), ElasticPair::on_rigid(kSteel));
    std::printf("t = dx/1000, E1 = %.3g Pa: %.3g of the substrate's products\n", layer.youngs_modulus, error);
    EXPECT_LT(error, 5e-3);
  }
}

// The smoothed closed forms tend to the point-load ones as the height goes
// to 0, and at a height they equal a fine midpoint sum of the smoothed
// kernels (1/rho, x_a x_b/rho^3, x_a/(rho (rho + h))).
TEST(CoatedTangentialOperator, SmoothedRectanglesAreTheirKernelsIntegrals) {
  const double a = 0.5e-6;
  const double b = 0.8e-6;
  const double shear = 3e-11;
  const double directional = 1e-11;
  const double d = 2e-11;
  for (const double height : {0.3e-6, 2e-6}) {
    for (const auto& [x, y] :
         {std::pair{0.0, 0.0}, std::pair{0.4e-6, -0.7e-6}, std::pair{2.5e-6, 1e-6}, std::pair{-30e-6, 12e-6}}) {
      const kernels::TangentialCoefficients c =
          kernels::cerruti_rectangle_displacement(x, y, a, b, shear, directional, height);
      const kernels::CouplingCoefficients k = kernels::coupling_rectangle_displacement(x, y, a, b, d, height);
      constexpr int kSteps = 400;
      double xx = 0.0, yy = 0.0, xy = 0.0, cx = 0.0, cy = 0.0;
      for (int i = 0; i < kSteps; ++i) {
        for (int j = 0; j < kSteps; ++j) {
          const double s = x - (-a + (i + 0.5) * 2.0 * a / kSteps);
          const double t = y - (-b + (j + 0.5) * 2.0 * b / kSteps);
          const double rho = std::sqrt(s * s + t * t + height * height);
          const double r3 = rho * rho * rho;
          xx += (shear - directional) / rho + directional * s * s / r3;
          yy += (shear - directional) / rho + directional * t * t / r3;
          xy += directional * s * t / r3;
          cx += d * s / (rho * (rho + height));
          cy += d * t / (rho * (rho + height));
        }
      }
      const double area = 4.0 * a * b / (kSteps * kSteps);
      const double scale = area / (2.0 * 3.14159265358979323846);
      const double reference = std::abs(xx * scale);
      EXPECT_NEAR(c.xx, xx * scale, 1e-5 * reference) << x << ", " << y << ", h " << height;
      EXPECT_NEAR(c.yy, yy * scale, 1e-5 * reference) << x << ", " << y << ", h " << height;
      EXPECT_NEAR(c.xy, xy * scale, 1e-5 * reference) << x << ", " << y << ", h " << height;
      const double coupling_reference = std::hypot(cx, cy) * 0.5 * scale + 1e-6 * d * std::sqrt(a * b);
      EXPECT_NEAR(k.x, 0.5 * cx * scale, 1e-5 * coupling_reference) << x << ", " << y << ", h " << height;
      EXPECT_NEAR(k.y, 0.5 * cy * scale, 1e-5 * coupling_reference) << x << ", " << y << ", h " << height;
    }
  }
  // Height 1e-12 of the cell: the point-load rectangles.
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, std::pair{0.5e-6, 0.8e-6}, std::pair{3e-6, -2e-6}}) {
    const kernels::TangentialCoefficients c0 = kernels::cerruti_rectangle_displacement(x, y, a, b, shear, directional);
    const kernels::TangentialCoefficients c1 =
        kernels::cerruti_rectangle_displacement(x, y, a, b, shear, directional, 1e-18);
    const kernels::CouplingCoefficients k0 = kernels::coupling_rectangle_displacement(x, y, a, b, d);
    const kernels::CouplingCoefficients k1 = kernels::coupling_rectangle_displacement(x, y, a, b, d, 1e-18);
    EXPECT_NEAR(c1.xx, c0.xx, 1e-10 * std::abs(c0.xx));
    EXPECT_NEAR(c1.yy, c0.yy, 1e-10 * std::abs(c0.xx));
    EXPECT_NEAR(c1.xy, c0.xy, 1e-10 * std::abs(c0.xx));
    EXPECT_NEAR(k1.x, k0.x, 1e-10 * std::abs(c0.xx) * d / shear);
    EXPECT_NEAR(k1.y, k0.y, 1e-10 * std::abs(c0.xx) * d / shear);
  }
}

// Where the remainder cannot go in by DFT the operator refuses, naming why.
TEST(CoatedTangentialOperator, ThickLayersAndLinesAreRefused) {
  const ElasticPair thick = ElasticPair::coated({5e-6, kCeramic, kSteel});
  for (const Grid& grid : {Grid::plane(32, 32, 1e-6, 1e-6, Boundary::free), Grid::line(64, 1e-6, Boundary::free)}) {
    try {
      TangentialOperator op(grid, thick);
      ADD_FAILURE() << "accepted on " << grid.shape_string();
    } catch (const InputError& error) {
      const std::string what = error.what();
      EXPECT_NE(what.find("coated half-space's tangential compliance on the free"), std::string::npos) << what;
      EXPECT_NE(what.find("--boundary periodic"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace halfspace
