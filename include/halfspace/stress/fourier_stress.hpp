// The stress field of a half-space under a normal surface traction in
// Fourier space (Boussinesq's problem for one wavevector): the periodic
// grids' closed-form solution.
#pragma once

#include <array>
#include <complex>
#include <cstddef>

namespace halfspace::stress {

// The components in the order every array of six uses: xx, yy, zz, xy, xz, yz.
enum class Component { xx, yy, zz, xy, xz, yz };
inline constexpr std::size_t kComponentCount = 6;
inline constexpr std::array<const char*, kComponentCount> kComponentNames = {"sigma_xx", "sigma_yy", "sigma_zz",
                                                                             "sigma_xy", "sigma_xz", "sigma_yz"};

// The stress spectra at depth z (m, > 0) per unit pressure spectrum, for the
// surface pressure mode exp(i (kx x + ky y)) (kx, ky in rad/m), Poisson's
// ratio nu; compression negative. With q = |k| and e = exp(-q z):
//   zz = -(1 + q z) e,
//   xx = [(kx/q)^2 (q z - (1 - 2 nu)) - 2 nu] e,   yy likewise with ky,
//   xy = (kx ky / q^2) (q z - (1 - 2 nu)) e,
//   xz = i kx z e,   yz = i ky z e.
// The mean mode (q = 0) is a uniform pressure on a laterally confined body
// (periodic displacements have no mean lateral strain): zz = -1,
// xx = yy = -nu / (1 - nu), no shear. A line contact (ky = 0) gives the
// plane-strain field, yy = nu (xx + zz).
std::array<std::complex<double>, kComponentCount> fourier_stress(double kx, double ky, double z, double nu);

// The mean mode's component per unit mean pressure (the confined state
// above), for a body of Poisson's ratio nu; the layered solution uses it for
// each body too.
double confined_mean_stress(Component component, double nu);

// One component of the above, given decay = exp(-|k| z): the form the
// periodic stress loop evaluates for each wavevector.
std::complex<double> fourier_stress_component(Component component, double kx, double ky, double z, double decay,
                                              double nu);

// Whether a component's multiplier is odd in kx (xy, xz) or in ky (xy, yz).
bool odd_in_x(Component component);
bool odd_in_y(Component component);

}  // namespace halfspace::stress
