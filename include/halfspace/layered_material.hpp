// A coated half-space: an elastic layer of thickness t perfectly bonded to an
// elastic substrate, pressed by a rigid rough surface (issue 20).
#pragma once

#include "halfspace/material.hpp"

namespace halfspace {

struct LayeredMaterial {
  double thickness = 0.0;  // t, m
  ElasticBody layer;       // E1 (Pa), nu1
  ElasticBody substrate;   // E2 (Pa), nu2
};

// The accepted ranges: the program's physical ones, which also keep the
// kernel's arithmetic clear of overflow (docs/theory.md, "Coated half-space").
inline constexpr double kMinLayerThickness = 1e-12;  // m
inline constexpr double kMaxLayerThickness = 1e3;    // m
inline constexpr double kMinLayerModulus = 1e3;      // Pa
inline constexpr double kMaxLayerModulus = 1e15;     // Pa

// Throws InputError naming the quantity (layer thickness t, E1, nu1, E2, nu2),
// its value and the allowed range: t in [1e-12, 1e3] m, E in [1e3, 1e15] Pa,
// nu in (-1, 0.5]. Returns `material` unchanged.
const LayeredMaterial& validated(const LayeredMaterial& material);

// The plane-strain modulus E / (1 - nu^2) of one body (Pa): the composite
// modulus of that body against a rigid one.
double plane_strain_modulus(const ElasticBody& body);

}  // namespace halfspace
