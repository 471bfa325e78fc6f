// The periodic tangential symbol (tangential_fourier.hpp).
#include "halfspace/kernels/tangential_fourier.hpp"

#include <cmath>

namespace halfspace::kernels {

TangentialCoefficients tangential_spectrum(double qx, double qy, double shear, double directional) {
  const double q = std::hypot(qx, qy);
  if (q == 0.0) return {};
  const double q3 = q * q * q;
  return {shear / q - directional * qx * qx / q3, shear / q - directional * qy * qy / q3, -directional * qx * qy / q3};
}

}  // namespace halfspace::kernels
