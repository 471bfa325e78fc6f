// The elastic half-space a rigid surface is pressed into: homogeneous, given
// by its composite modulus E* (Pa, material.hpp), or coated (an elastic layer
// bonded to a substrate, layered_material.hpp). What the normal kernel, the
// operator factory and the solver factory take.
#pragma once

#include <variant>

#include "halfspace/layered_material.hpp"

namespace halfspace {

using HalfSpace = std::variant<double, LayeredMaterial>;

// The modulus at a contact edge's scale, which sets an adhesive law's
// cohesive zone: a homogeneous body's E* (Pa), or a coating's layer's
// plane-strain modulus (the layer meets the rigid surface).
inline double contact_modulus(const HalfSpace& half_space) {
  if (const auto* coating = std::get_if<LayeredMaterial>(&half_space)) return plane_strain_modulus(coating->layer);
  return std::get<double>(half_space);
}

}  // namespace halfspace
