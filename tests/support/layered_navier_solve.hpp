// The bonded layer's surface displacement under one surface-traction mode,
// solved directly from Navier's equations in plane strain: the independent
// reference for the coated kernels (layered_fourier, layered_tangential_fourier).
// The growing terms are taken relative to z = t and the stress rows divided
// by mu1, which keeps the 6 x 6 system's condition number below 1e5 for
// q t <= 5.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "halfspace/layered_material.hpp"

namespace halfspace::testing {

// The bonded layer under a surface traction of one mode (q = 1/m), solved
// from Navier's equations in plane strain, a method apart from the kernel's
// Airy functions: u_x = U(z) sin(qx), u_z = W(z) cos(qx), U = (a1 + a2 z)
// e^{-qz} + (a3 + a4 z) e^{q(z - t)} in the layer, the decaying terms in the
// substrate (z down); sigma_zz = -p cos(qx), sigma_xz = -s sin(qx) on the
// surface, U, W, sigma_zz, sigma_xz continuous at z = t. Returns (U(0),
// W(0)) in metres for p, s in Pa.
inline std::array<double, 2> layered_surface_displacement(const LayeredMaterial& m, double p, double s) {
  struct Body {
    double lam, mu;
  };
  auto body = [](const ElasticBody& b) {
    const double e = b.youngs_modulus;
    const double nu = b.poissons_ratio;
    return Body{e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))};
  };
  const double q = 1.0;
  const double t = m.thickness;
  // Rows U, W, sigma_zz, sigma_xz; columns a1..a4 at depth z.
  auto fields = [q, t](const Body& b, double z) {
    const double l = b.lam;
    const double mu = b.mu;
    const double d = std::exp(-q * z);
    const double g = std::exp(q * (z - t));
    Eigen::Matrix4d f;
    f << d, z * d, g, z * g,                                                                               //
        d, (l * q * z + l + mu * q * z + 3 * mu) * d / (q * (l + mu)), -g,                                 //
        -(l * q * z - l + mu * q * z - 3 * mu) * g / (q * (l + mu)),                                       //
        -2 * mu * q * d, -2 * mu * (l * q * z + l + mu * q * z + 2 * mu) * d / (l + mu), -2 * mu * q * g,  //
        -2 * mu * (l * q * z - l + mu * q * z - 2 * mu) * g / (l + mu),                                    //
        -2 * mu * q * d, -2 * mu * (l * q * z + mu * q * z + mu) * d / (l + mu), 2 * mu * q * g,           //
        2 * mu * (l * q * z + mu * q * z - mu) * g / (l + mu);
    return f;
  };
  const Body layer = body(m.layer);
  const Body substrate = body(m.substrate);
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  const Eigen::Matrix4d top = fields(layer, 0.0);
  a.block<2, 4>(0, 0) = top.block<2, 4>(2, 0);
  rhs(0) = -p;
  rhs(1) = -s;
  a.block<4, 4>(2, 0) = fields(layer, t);
  a.block<4, 2>(2, 4) = -fields(substrate, t).block<4, 2>(0, 0);
  for (const int row : {0, 1, 4, 5}) {
    a.row(row) /= layer.mu;
    rhs(row) /= layer.mu;
  }
  const Eigen::Matrix<double, 6, 1> x = a.fullPivLu().solve(rhs);
  return {top.row(0).dot(x.head<4>()), top.row(1).dot(x.head<4>())};
}

}  // namespace halfspace::testing
