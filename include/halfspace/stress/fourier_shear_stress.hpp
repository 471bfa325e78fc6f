// The stress field of a half-space under a tangential surface traction in
// Fourier space (Cerruti's problem for one wavevector): the periodic grids'
// closed-form solution beside the pressure's (fourier_stress.hpp).
#pragma once

#include <array>
#include <complex>

#include "halfspace/stress/fourier_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

// The stress spectra at depth z (m, > 0) per unit spectrum of a shear along x
// (sigma_xz = -q_x at the surface), for the mode exp(i (kx x + ky y)) and
// Poisson's ratio nu. With q = |k| and e = exp(-q z):
//   xx = i (kx/q) [2 + 2 nu ky^2/q^2 - kx^2 z/q] e,
//   yy = i (kx/q) [2 nu kx^2/q^2 - ky^2 z/q] e,
//   zz = i kx z e,
//   xy = i (ky/q) [1 - (kx^2/q^2) (2 nu + q z)] e,
//   xz = (kx^2 z/q - 1) e,   yz = (kx ky z/q) e.
// A shear along y is the same with x and y exchanged. The mean mode (q = 0)
// is a uniform shear: xz = -1 (yz = -1 along y), nothing else. A line
// contact (ky = 0) gives the plane-strain field for a shear along x and the
// antiplane field (xy, yz only) for a shear along y.
std::complex<double> fourier_shear_stress_component(Component component, Traction direction, double kx, double ky,
                                                    double z, double decay, double nu);

// All six (Component order); `direction` is Traction::shear_x or shear_y.
std::array<std::complex<double>, kComponentCount> fourier_shear_stress(Traction direction, double kx, double ky,
                                                                       double z, double nu);

// The multiplier of any traction: fourier_stress_component for the pressure,
// the above for a shear.
std::complex<double> fourier_traction_stress_component(Component component, Traction traction, double kx, double ky,
                                                       double z, double decay, double nu);

}  // namespace halfspace::stress
