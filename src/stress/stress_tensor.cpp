// Scalar measures of a stress tensor. The principal stresses of a symmetric
// 3x3 tensor come from the trigonometric solution of its characteristic cubic
// (Smith 1961, "Eigenvalues of a symmetric 3x3 matrix", Comm. ACM 4(4) 168):
// with m = tr/3, K = s - m I, p = |K|^2 / 6 and cos(3 phi) = det(K) / (2 p^(3/2)),
// the eigenvalues are m + 2 sqrt(p) cos(phi + 2 pi k / 3), so the largest minus
// the smallest is 2 sqrt(3 p) sin(phi + pi/3).
#include "halfspace/stress/stress_tensor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace halfspace::stress {

double von_mises(const StressTensor& s) {
  const double a = s.xx - s.yy;
  const double b = s.yy - s.zz;
  const double c = s.zz - s.xx;
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz));
}

double max_shear(const StressTensor& s) {
  const double m = hydrostatic(s);
  const double kxx = s.xx - m;
  const double kyy = s.yy - m;
  const double kzz = s.zz - m;
  const double p = (kxx * kxx + kyy * kyy + kzz * kzz + 2.0 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz)) / 6.0;
  if (p <= 0.0) return 0.0;  // isotropic: every direction is principal
  const double det =
      kxx * (kyy * kzz - s.yz * s.yz) - s.xy * (s.xy * kzz - s.yz * s.xz) + s.xz * (s.xy * s.yz - kyy * s.xz);
  // Rounding can push the cosine just outside [-1, 1].
  const double cos3phi = std::clamp(det / (2.0 * p * std::sqrt(p)), -1.0, 1.0);
  const double phi = std::acos(cos3phi) / 3.0;
  return std::sqrt(3.0 * p) * std::sin(phi + std::numbers::pi / 3.0);
}

double hydrostatic(const StressTensor& s) {
  return (s.xx + s.yy + s.zz) / 3.0;
}

}  // namespace halfspace::stress
