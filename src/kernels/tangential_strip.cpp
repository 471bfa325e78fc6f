// Plane-strain tangential strip coefficients: the normal strip's integral of
// the logarithmic line-load kernel with each direction's compliance.
#include "halfspace/kernels/tangential_strip.hpp"

#include "halfspace/kernels/plane_strain_strip.hpp"

namespace halfspace::kernels {

TangentialCoefficients tangential_strip_displacement(double d, double width, double e_star, double shear) {
  // plane_strain_strip_displacement has compliance 2/E*: the antiplane one,
  // shear, is that of the modulus 2/shear.
  return {plane_strain_strip_displacement(d, width, e_star), plane_strain_strip_displacement(d, width, 2.0 / shear),
          0.0};
}

}  // namespace halfspace::kernels
