// The bonded layer under one surface-traction mode, solved directly from
// Navier's equations: the independent reference for the coated kernels
// (layered_fourier, layered_tangential_fourier) and the coated stresses
// (layered_fourier_stress, layered_fourier_shear_stress). Plane strain for
// the pressure and the shear along the wave vector, antiplane for the shear
// across it. The growing terms are taken relative to z = t and the stress
// rows divided by mu1, which keeps the 6 x 6 system's condition number below
// 1e5 for q t <= 5.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "halfspace/layered_material.hpp"

namespace halfspace::testing {

// Lame's constants of one body.
struct NavierBody {
  double lam, mu;
};

inline NavierBody navier_body(const ElasticBody& b) {
  const double e = b.youngs_modulus;
  const double nu = b.poissons_ratio;
  return NavierBody{e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))};
}

// Plane strain, q = 1/m: u_x = U(z) sin(qx), u_z = W(z) cos(qx), with U =
// (a1 + a2 z) e^{-qz} + (a3 + a4 z) e^{q(z - t)} (z down). Rows U, W,
// sigma_zz, sigma_xz (the amplitudes of cos, sin); columns a1..a4 at depth z.
inline Eigen::Matrix4d navier_plane_strain_fields(const NavierBody& b, double t, double z) {
  const double q = 1.0;
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
}

// The plane-strain mode (q = 1/m) under sigma_zz = -p cos(qx), sigma_xz =
// -s sin(qx) on the surface (Pa), with U, W, sigma_zz, sigma_xz continuous at
// z = t: the layer's a1..a4 and the substrate's decaying a1, a2.
struct LayeredNavierPlaneStrain {
  LayeredMaterial material;
  Eigen::Matrix<double, 6, 1> coefficients;

  // (U, W, sigma_zz, sigma_xz, sigma_xx, sigma_yy) at depth z (m) in the
  // layer or the substrate; sigma_xx, sigma_yy (cos amplitudes) from Hooke's
  // law with eps_xx = q U and eps_zz = W', W' read off sigma_zz.
  std::array<double, 6> at(double z, bool in_layer) const {
    const NavierBody b = navier_body(in_layer ? material.layer : material.substrate);
    const Eigen::Matrix4d f = navier_plane_strain_fields(b, material.thickness, z);
    const Eigen::Vector4d v = in_layer ? Eigen::Vector4d(f * coefficients.head<4>())
                                       : Eigen::Vector4d(f.leftCols<2>() * coefficients.tail<2>());
    const double q = 1.0;
    const double w_slope = (v(2) - b.lam * q * v(0)) / (b.lam + 2 * b.mu);
    return {v(0), v(1), v(2), v(3), (b.lam + 2 * b.mu) * q * v(0) + b.lam * w_slope, b.lam * (q * v(0) + w_slope)};
  }
};

inline LayeredNavierPlaneStrain solve_layered_navier(const LayeredMaterial& m, double p, double s) {
  const double t = m.thickness;
  const NavierBody layer = navier_body(m.layer);
  const NavierBody substrate = navier_body(m.substrate);
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  const Eigen::Matrix4d top = navier_plane_strain_fields(layer, t, 0.0);
  a.block<2, 4>(0, 0) = top.block<2, 4>(2, 0);
  rhs(0) = -p;
  rhs(1) = -s;
  a.block<4, 4>(2, 0) = navier_plane_strain_fields(layer, t, t);
  a.block<4, 2>(2, 4) = -navier_plane_strain_fields(substrate, t, t).block<4, 2>(0, 0);
  for (const int row : {0, 1, 4, 5}) {
    a.row(row) /= layer.mu;
    rhs(row) /= layer.mu;
  }
  return {m, a.fullPivLu().solve(rhs)};
}

// (U(0), W(0)) in metres of the plane-strain mode for p, s in Pa.
inline std::array<double, 2> layered_surface_displacement(const LayeredMaterial& m, double p, double s) {
  const std::array<double, 6> surface = solve_layered_navier(m, p, s).at(0.0, true);
  return {surface[0], surface[1]};
}

// The antiplane mode (q = 1/m) under sigma_yz = -s sin(qx) on the surface:
// u_y = V(z) sin(qx), V = a e^{-qz} + b e^{q(z - t)} in the layer, c
// e^{-q(z - t)} below, V and mu V' continuous at z = t (a 3 x 3 system).
struct LayeredNavierAntiplane {
  LayeredMaterial material;
  Eigen::Vector3d coefficients;

  // (V, sigma_yz = mu V' (sin amplitude), sigma_xy = mu q V (cos amplitude))
  // at depth z (m) in the layer or the substrate.
  std::array<double, 3> at(double z, bool in_layer) const {
    const double t = material.thickness;
    const double mu = navier_body(in_layer ? material.layer : material.substrate).mu;
    double v = 0.0;
    double slope = 0.0;
    if (in_layer) {
      v = coefficients(0) * std::exp(-z) + coefficients(1) * std::exp(z - t);
      slope = -coefficients(0) * std::exp(-z) + coefficients(1) * std::exp(z - t);
    } else {
      v = coefficients(2) * std::exp(-(z - t));
      slope = -v;
    }
    return {v, mu * slope, mu * v};
  }
};

inline LayeredNavierAntiplane solve_layered_antiplane(const LayeredMaterial& m, double s) {
  const double mu1 = navier_body(m.layer).mu;
  const double mu2 = navier_body(m.substrate).mu;
  const double e = std::exp(-m.thickness);
  Eigen::Matrix3d a;
  a << -1.0, e, 0.0,  //
      e, 1.0, -1.0,   //
      -e, 1.0, mu2 / mu1;
  const Eigen::Vector3d rhs(-s / mu1, 0.0, 0.0);
  return {m, a.fullPivLu().solve(rhs)};
}

}  // namespace halfspace::testing
