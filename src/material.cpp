// Composite modulus of two elastic bodies, with input validation.
#include "halfspace/material.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

// Compliance (1 - nu^2)/E of one body; `index` names it in messages (E1, nu1...).
double compliance(const ElasticBody& body, int index) {
  const double e = body.youngs_modulus;
  const double nu = body.poissons_ratio;
  if (!(std::isfinite(e) && e > 0.0)) {
    throw InputError(fmt::format("Young's modulus E{} = {} Pa is invalid: must be positive and finite", index, e));
  }
  if (!(std::isfinite(nu) && nu > -1.0 && nu <= 0.5)) {
    throw InputError(fmt::format("Poisson's ratio nu{} = {} is invalid: allowed range is (-1, 0.5]", index, nu));
  }
  return (1.0 - nu * nu) / e;
}

}  // namespace

double composite_modulus(const ElasticBody& body1, const ElasticBody& body2) {
  return 1.0 / (compliance(body1, 1) + compliance(body2, 2));
}

double checked_composite_modulus(double e_star) {
  if (!(std::isfinite(e_star) && e_star > 0.0)) {
    throw InputError(fmt::format("composite modulus E* = {} Pa is invalid: must be positive and finite", e_star));
  }
  return e_star;
}

}  // namespace halfspace
