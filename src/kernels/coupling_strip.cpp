// The plane-strain coupling strip (coupling_strip.hpp).
#include "halfspace/kernels/coupling_strip.hpp"

#include <cmath>

namespace halfspace::kernels {

CouplingCoefficients coupling_strip_displacement(double d, double width, double coupling) {
  const double half = 0.5 * width;
  // Odd in d exactly: evaluated on |d|.
  const double value = 0.25 * coupling * (std::abs(d) + half - std::abs(std::abs(d) - half));
  return {d < 0.0 ? -value : value, 0.0};
}

}  // namespace halfspace::kernels
