// Boussinesq's problem for one Fourier mode. With the Papkovich-Neuber
// potentials B = (0, 0, b) e^{-qz} E and B0 = c e^{-qz} E (E = e^{i k.x}),
// 2G u = 4 (1 - nu) B - grad(z B_z + B0); the traction-free shear at z = 0
// fixes q c = -(1 - 2 nu) b and szz(0) = -p fixes q b = p, which gives the
// multipliers of the header. They agree with Johnson's (1985) potential form
// of the point-load solution (rectangle_stress.cpp) under the transforms
// int e^{-ik.x} / rho dA = 2 pi e^{-qz} / q, and reduce to Johnson's sec. 2.6
// sinusoidal plane-strain field for ky = 0.
#include "halfspace/stress/fourier_stress.hpp"

#include <cmath>

namespace halfspace::stress {

double confined_mean_stress(Component component, double nu) {
  switch (component) {
    case Component::xx:
    case Component::yy:
      return -nu / (1.0 - nu);
    case Component::zz:
      return -1.0;
    default:
      return 0.0;
  }
}

std::complex<double> fourier_stress_component(Component component, double kx, double ky, double z, double decay,
                                              double nu) {
  const double q2 = kx * kx + ky * ky;
  if (q2 == 0.0) return confined_mean_stress(component, nu);
  const double qz = std::sqrt(q2) * z;
  const double bracket = (qz - (1.0 - 2.0 * nu)) * decay / q2;
  switch (component) {
    case Component::xx:
      return kx * kx * bracket - 2.0 * nu * decay;
    case Component::yy:
      return ky * ky * bracket - 2.0 * nu * decay;
    case Component::zz:
      return -(1.0 + qz) * decay;
    case Component::xy:
      return kx * ky * bracket;
    case Component::xz:
      return {0.0, kx * z * decay};
    case Component::yz:
      return {0.0, ky * z * decay};
  }
  return 0.0;
}

std::array<std::complex<double>, kComponentCount> fourier_stress(double kx, double ky, double z, double nu) {
  const double decay = std::exp(-std::hypot(kx, ky) * z);
  std::array<std::complex<double>, kComponentCount> result;
  for (std::size_t c = 0; c < kComponentCount; ++c) {
    result[c] = fourier_stress_component(static_cast<Component>(c), kx, ky, z, decay, nu);
  }
  return result;
}

bool odd_in_x(Component component) {
  return component == Component::xy || component == Component::xz;
}

bool odd_in_y(Component component) {
  return component == Component::xy || component == Component::yz;
}

}  // namespace halfspace::stress
