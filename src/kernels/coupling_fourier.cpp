// The periodic coupling symbol (coupling_fourier.hpp).
#include "halfspace/kernels/coupling_fourier.hpp"

#include <cmath>

namespace halfspace::kernels {

CouplingCoefficients coupling_spectrum(double qx, double qy, double coupling) {
  const double q2 = qx * qx + qy * qy;
  if (q2 == 0.0) return {};
  const double f = -0.5 * coupling / q2;
  return {f * qx, f * qy};
}

}  // namespace halfspace::kernels
