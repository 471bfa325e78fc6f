// Elastic constants of the two bodies and their composite (contact) modulus
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, in Pa.
#pragma once

namespace halfspace {

struct ElasticBody {
  double youngs_modulus = 0.0;  // E, Pa
  double poissons_ratio = 0.0;  // nu, dimensionless
};

// Throws InputError naming the body (E1, nu1 for index 1, ...) unless E is
// positive, finite and normal (not denormal; or +inf, a rigid body, where
// `rigid_allowed`) and nu is in (-1, 0.5]; returns `body`.
const ElasticBody& checked_body(const ElasticBody& body, int index, bool rigid_allowed = false);

// Composite modulus E* (Pa) of two bodies. Throws InputError naming the body
// when E is not positive, finite and normal (not denormal), or nu is outside
// (-1, 0.5], and naming all four when E* itself is not.
double composite_modulus(const ElasticBody& body1, const ElasticBody& body2);

// Checks a directly given E* (Pa): throws InputError unless positive, finite
// and normal (not denormal). Any scale is accepted (tests use E* = 1); the
// program sets physical bounds of its own.
double checked_composite_modulus(double e_star);

}  // namespace halfspace
