// The stress tensor at one point (Pa, compression negative) and the scalar
// measures of it that yield criteria use: von Mises, maximum shear (Tresca)
// and hydrostatic stress.
#pragma once

namespace halfspace::stress {

struct StressTensor {
  double xx = 0.0;
  double yy = 0.0;
  double zz = 0.0;
  double xy = 0.0;
  double xz = 0.0;
  double yz = 0.0;
};

// sqrt(3 J2): sqrt(((xx-yy)^2 + (yy-zz)^2 + (zz-xx)^2) / 2 + 3 (xy^2 + xz^2 + yz^2)).
double von_mises(const StressTensor& s);

// Half the difference of the largest and smallest principal stresses (the
// Tresca shear), from the closed-form eigenvalues of the symmetric tensor.
double max_shear(const StressTensor& s);

// The mean normal stress (xx + yy + zz) / 3.
double hydrostatic(const StressTensor& s);

}  // namespace halfspace::stress
