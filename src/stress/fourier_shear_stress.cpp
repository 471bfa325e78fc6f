// Cerruti's problem for one Fourier mode, split in the frame of the wave
// vector: x' along k (q = |k|, c = kx/q, s = ky/q), y' across it.
//
// Along k (plane strain in x', z): the Airy function
// phi = (A + B q z) e^{-qz} E / q^2 (E = e^{i q x'}) gives
// szz = -(A + B q z) e E, sx'x' = (A - 2B + B q z) e E,
// sx'z = -i (B - A - B q z) e E; the unloaded normal (A = 0) and the unit
// shear sx'z(0) = -1 (B = -i) leave
//   sx'x' = i (2 - q z) e,  szz = i q z e,  sx'z = (q z - 1) e,
//   sy'y' = nu (sx'x' + szz) = 2 i nu e.
// Across k (antiplane): u_y' = W e^{-qz} E is harmonic; sy'z(0) = -1 gives
//   sy'z = -e,  sx'y' = i e.
// A unit shear along x has the parts c along k and -s across it; rotating
// back (s_lab = R s' R^T) gives the multipliers of the header. Under the
// transforms FT(1/rho) = 2 pi e/q, FT(ln(rho + z)) = -2 pi e/q^2 and
// FT(z ln(rho + z) - rho) = 2 pi e/q^3 they are Cerruti's point-force
// stresses (Johnson 1985, eq. 3.87), which rectangle_shear_stress.cpp
// integrates over a cell; the tests check one against the other.
#include "halfspace/stress/fourier_shear_stress.hpp"

#include <cmath>
#include <utility>

namespace halfspace::stress {
namespace {

// The multiplier of a shear along x.
std::complex<double> shear_x_component(Component component, double kx, double ky, double z, double decay, double nu) {
  const double q2 = kx * kx + ky * ky;
  if (q2 == 0.0) return component == Component::xz ? -1.0 : 0.0;
  const double q = std::sqrt(q2);
  const double cx = kx / q;
  const double cy = ky / q;
  switch (component) {
    case Component::xx:
      return {0.0, cx * (2.0 + 2.0 * nu * cy * cy - cx * kx * z) * decay};
    case Component::yy:
      return {0.0, cx * (2.0 * nu * cx * cx - cy * ky * z) * decay};
    case Component::zz:
      return {0.0, kx * z * decay};
    case Component::xy:
      return {0.0, cy * (1.0 - cx * cx * (2.0 * nu + q * z)) * decay};
    case Component::xz:
      return (cx * kx * z - 1.0) * decay;
    case Component::yz:
      return cx * ky * z * decay;
  }
  return 0.0;
}

// The component a shear along x gives in place of `component` under the
// exchange of x and y.
Component exchanged(Component component) {
  switch (component) {
    case Component::xx:
      return Component::yy;
    case Component::yy:
      return Component::xx;
    case Component::xz:
      return Component::yz;
    case Component::yz:
      return Component::xz;
    default:
      return component;
  }
}

}  // namespace

std::complex<double> fourier_shear_stress_component(Component component, Traction direction, double kx, double ky,
                                                    double z, double decay, double nu) {
  if (direction == Traction::shear_y) return shear_x_component(exchanged(component), ky, kx, z, decay, nu);
  return shear_x_component(component, kx, ky, z, decay, nu);
}

std::array<std::complex<double>, kComponentCount> fourier_shear_stress(Traction direction, double kx, double ky,
                                                                       double z, double nu) {
  const double decay = std::exp(-std::hypot(kx, ky) * z);
  std::array<std::complex<double>, kComponentCount> result;
  for (std::size_t c = 0; c < kComponentCount; ++c) {
    result[c] = fourier_shear_stress_component(static_cast<Component>(c), direction, kx, ky, z, decay, nu);
  }
  return result;
}

std::complex<double> fourier_traction_stress_component(Component component, Traction traction, double kx, double ky,
                                                       double z, double decay, double nu) {
  if (traction == Traction::pressure) return fourier_stress_component(component, kx, ky, z, decay, nu);
  return fourier_shear_stress_component(component, traction, kx, ky, z, decay, nu);
}

}  // namespace halfspace::stress
