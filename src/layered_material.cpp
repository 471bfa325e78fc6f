// Validation of a coated half-space's description.
#include "halfspace/layered_material.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

void check_body(const ElasticBody& body, std::string_view which, int index) {
  const double e = body.youngs_modulus;
  if (!(e >= kMinLayerModulus && e <= kMaxLayerModulus)) {
    throw InputError(fmt::format("{} Young's modulus E{} = {:g} Pa is invalid: allowed range is [{:g}, {:g}] Pa", which,
                                 index, e, kMinLayerModulus, kMaxLayerModulus));
  }
  const double nu = body.poissons_ratio;
  if (!(nu > -1.0 && nu <= 0.5)) {
    throw InputError(
        fmt::format("{} Poisson's ratio nu{} = {:g} is invalid: allowed range is (-1, 0.5]", which, index, nu));
  }
}

}  // namespace

const LayeredMaterial& validated(const LayeredMaterial& material) {
  const double t = material.thickness;
  if (!(t >= kMinLayerThickness && t <= kMaxLayerThickness)) {
    throw InputError(fmt::format("layer thickness t = {:g} m is invalid: allowed range is [{:g}, {:g}] m", t,
                                 kMinLayerThickness, kMaxLayerThickness));
  }
  check_body(material.layer, "layer", 1);
  check_body(material.substrate, "substrate", 2);
  return material;
}

double plane_strain_modulus(const ElasticBody& body) {
  return body.youngs_modulus / (1.0 - body.poissons_ratio * body.poissons_ratio);
}

}  // namespace halfspace
