// The two bodies' compliance factors (elastic_pair.hpp).
#include "halfspace/elastic_pair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "halfspace/error.hpp"
#include "halfspace/kernels/coupling_fourier.hpp"
#include "halfspace/kernels/layered_tangential_fourier.hpp"
#include "halfspace/kernels/tangential_fourier.hpp"

namespace halfspace {
namespace {

// 1/G of a body (1/Pa), 0 for a rigid one; `index` names it in messages.
double inverse_shear_modulus(const ElasticBody& body, int index) {
  checked_body(body, index, index == 2);
  const double e = body.youngs_modulus;
  return std::isinf(e) ? 0.0 : 2.0 * (1.0 + body.poissons_ratio) / e;
}

}  // namespace

ElasticPair::ElasticPair(const ElasticBody& body1, const ElasticBody& body2) : body1_(body1), body2_(body2) {
  const double c1 = inverse_shear_modulus(body1, 1);
  const double c2 = inverse_shear_modulus(body2, 2);
  const double nu1 = body1.poissons_ratio;
  const double nu2 = body2.poissons_ratio;
  shear_compliance_ = c1 + c2;
  directional_compliance_ = nu1 * c1 + nu2 * c2;
  coupling_compliance_ = (1.0 - 2.0 * nu1) * c1 - (1.0 - 2.0 * nu2) * c2;
  normal_compliance_ = (1.0 - nu1) * c1 + (1.0 - nu2) * c2;
  if (!(std::isnormal(normal_compliance_) && std::isnormal(shear_compliance_))) {
    throw InputError(fmt::format(
        "the compliances of E1 = {} Pa, nu1 = {}, E2 = {} Pa, nu2 = {} are invalid: must be positive and finite",
        format_number(body1.youngs_modulus), format_number(nu1), format_number(body2.youngs_modulus),
        format_number(nu2)));
  }
}

ElasticBody ElasticPair::rigid() {
  return {std::numeric_limits<double>::infinity(), 0.0};
}

ElasticPair ElasticPair::coated(const LayeredMaterial& coating) {
  ElasticPair pair(validated(coating).layer, rigid());
  pair.coating_ = coating;
  return pair;
}

HalfSpace ElasticPair::half_space() const {
  if (coating_) return *coating_;
  return composite_modulus();
}

void ElasticPair::symbols(double qx, double qy, kernels::TangentialCoefficients& tangential,
                          kernels::CouplingCoefficients& coupling) const {
  // The layered kernel holds the material and two ratios: made per call,
  // it costs nothing beside its two solves.
  if (coating_) {
    kernels::LayeredTangentialKernel(*coating_).symbols(qx, qy, tangential, coupling);
    return;
  }
  tangential = kernels::tangential_spectrum(qx, qy, shear_compliance_, directional_compliance_);
  coupling = kernels::coupling_spectrum(qx, qy, coupling_compliance_);
}

kernels::TangentialCoefficients ElasticPair::tangential_symbol(double qx, double qy) const {
  if (coating_) return kernels::LayeredTangentialKernel(*coating_).tangential(qx, qy);
  return kernels::tangential_spectrum(qx, qy, shear_compliance_, directional_compliance_);
}

kernels::CouplingCoefficients ElasticPair::coupling_symbol(double qx, double qy) const {
  if (coating_) return kernels::LayeredTangentialKernel(*coating_).coupling(qx, qy);
  return kernels::coupling_spectrum(qx, qy, coupling_compliance_);
}

double ElasticPair::composite_modulus() const {
  return checked_composite_modulus(2.0 / normal_compliance_);
}

double ElasticPair::dundurs_beta() const {
  return coupling_compliance_ / (2.0 * normal_compliance_);
}

bool ElasticPair::similar() const {
  if (coating_) {
    const ElasticBody& layer = coating_->layer;
    const ElasticBody& substrate = coating_->substrate;
    const bool one_material =
        layer.youngs_modulus == substrate.youngs_modulus && layer.poissons_ratio == substrate.poissons_ratio;
    if (!one_material) return false;
  }
  return std::abs(dundurs_beta()) <= 1e-12;
}

}  // namespace halfspace
