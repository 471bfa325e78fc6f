// Composite modulus of two elastic bodies, with input validation.
#include "halfspace/material.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

// Compliance (1 - nu^2)/E of one body; `index` names it in messages (E1, nu1...).
double compliance(const ElasticBody& body, int index) {
  checked_body(body, index);
  return (1.0 - body.poissons_ratio * body.poissons_ratio) / body.youngs_modulus;
}

}  // namespace

const ElasticBody& checked_body(const ElasticBody& body, int index, bool rigid_allowed) {
  const double e = body.youngs_modulus;
  const double nu = body.poissons_ratio;
  const bool rigid = rigid_allowed && e == std::numeric_limits<double>::infinity();
  if (!rigid && !(std::isnormal(e) && e > 0.0)) {
    throw InputError(fmt::format("Young's modulus E{} = {} Pa is invalid: must be positive, finite and not denormal{}",
                                 index, format_number(e), rigid_allowed ? " (or inf for a rigid body)" : ""));
  }
  if (!(std::isfinite(nu) && nu > -1.0 && nu <= 0.5)) {
    throw InputError(
        fmt::format("Poisson's ratio nu{} = {} is invalid: allowed range is (-1, 0.5]", index, format_number(nu)));
  }
  return body;
}

double composite_modulus(const ElasticBody& body1, const ElasticBody& body2) {
  // Each compliance may be fine and their sum still overflow or vanish.
  const double e_star = 1.0 / (compliance(body1, 1) + compliance(body2, 2));
  if (!(std::isnormal(e_star) && e_star > 0.0)) {
    throw InputError(fmt::format(
        "composite modulus E* = {} Pa of E1 = {} Pa, nu1 = {}, E2 = {} Pa, nu2 = {} is invalid: must be positive, "
        "finite and not denormal",
        format_number(e_star), format_number(body1.youngs_modulus), format_number(body1.poissons_ratio),
        format_number(body2.youngs_modulus), format_number(body2.poissons_ratio)));
  }
  return e_star;
}

double checked_composite_modulus(double e_star) {
  // A denormal E* passes "positive and finite" but its reciprocal, in every
  // kernel, is infinite.
  if (!(std::isnormal(e_star) && e_star > 0.0)) {
    throw InputError(
        fmt::format("composite modulus E* = {} Pa is invalid: must be positive, finite and not denormal", e_star));
  }
  return e_star;
}

}  // namespace halfspace
