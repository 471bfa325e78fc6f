// The two elastic bodies of a contact, each with its own E and nu: what the
// normal problem needs (the composite modulus E*) and what the tangential one
// needs besides, since E* alone does not fix it (Johnson 1985, sec. 2.2, 3.2;
// docs/theory.md, "Friction"). Body 2 may be rigid (E2 = +inf).
//
// Relative surface displacements of the two bodies add their compliances
// (G = E / (2 (1 + nu)), the shear modulus):
//   normal                  (1 - nu1)/G1 + (1 - nu2)/G2 = 2/E*
//   tangential, isotropic   1/G1 + 1/G2
//   tangential, along q     nu1/G1 + nu2/G2 (subtracted in the direction of the wave vector)
//   normal-tangential       (1 - 2 nu1)/G1 - (1 - 2 nu2)/G2 (zero for similar bodies)
// and Dundurs' beta = coupling / (2 normal compliance), zero for elastically
// similar bodies: then the normal and tangential problems are uncoupled.
//
// Body 1 may instead be a coated half-space (a layer on a substrate,
// layered_material.hpp) against a rigid body 2: its compliances then depend
// on the wavelength, so the pair gives them per Fourier mode (the symbols
// below, kernels/layered_tangential_fourier.hpp) and the normal kernel takes
// the coating itself (half_space()).
#pragma once

#include <optional>

#include "halfspace/half_space.hpp"
#include "halfspace/kernels/coupling_coefficients.hpp"
#include "halfspace/kernels/tangential_coefficients.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/material.hpp"

namespace halfspace {

class ElasticPair {
 public:
  // Throws InputError naming the body when E is not positive and normal
  // (body 2 may be +inf, rigid) or nu is outside (-1, 0.5].
  ElasticPair(const ElasticBody& body1, const ElasticBody& body2);
  // One elastic body (E, nu) against a rigid one.
  static ElasticPair on_rigid(const ElasticBody& body) { return {body, rigid()}; }
  // Two bodies of the same material.
  static ElasticPair similar(const ElasticBody& body) { return {body, body}; }
  static ElasticBody rigid();
  // A coated half-space (body 1) against a rigid body 2. Throws InputError
  // naming the quantity if `coating` is out of range (layered_material.hpp).
  static ElasticPair coated(const LayeredMaterial& coating);

  // The coating of body 1, if it is coated. Then body1() is the layer and
  // body2() rigid, and the scalar factors below (composite_modulus() to
  // dundurs_beta()) are the layer's against the rigid body: the short-wave
  // limit of the symbols, at the scale where the layer meets the surface.
  const std::optional<LayeredMaterial>& coating() const { return coating_; }
  // What the normal kernel takes (half_space.hpp): E* of a homogeneous
  // pair, or the coating.
  HalfSpace half_space() const;

  const ElasticBody& body1() const { return body1_; }
  const ElasticBody& body2() const { return body2_; }

  // E* (Pa): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
  double composite_modulus() const;
  // 1/G1 + 1/G2 (1/Pa): the isotropic tangential compliance factor.
  double shear_compliance() const { return shear_compliance_; }
  // nu1/G1 + nu2/G2 (1/Pa): the factor of the part along the wave vector
  // (periodic) or along the offset (Cerruti's nu x^2/rho^3 term).
  double directional_compliance() const { return directional_compliance_; }
  // (1 - 2 nu1)/G1 - (1 - 2 nu2)/G2 (1/Pa): the normal-tangential coupling.
  double coupling_compliance() const { return coupling_compliance_; }
  // Dundurs' beta = coupling / (2 ((1 - nu1)/G1 + (1 - nu2)/G2)), in [-0.5, 0.5].
  double dundurs_beta() const;
  // Whether the normal and tangential problems uncouple (beta = 0 to
  // rounding). A coated body couples unless the layer is its substrate's
  // material with nu = 0.5: the layer-substrate interface couples the two
  // problems even for incompressible materials of different moduli.
  bool similar() const;

  // The periodic compliances per Fourier mode (qx, qy, rad/m; zero at q =
  // 0): the 2x2 tangential symbol of kernels/tangential_fourier.hpp and the
  // coupling symbol c of kernels/coupling_fourier.hpp, in their units and
  // signs. A homogeneous pair's from its factors above, a coated body's
  // from two small solves per mode (layered_tangential_fourier.hpp).
  kernels::TangentialCoefficients tangential_symbol(double qx, double qy) const;
  kernels::CouplingCoefficients coupling_symbol(double qx, double qy) const;
  // Both at once (for a coated body, one pair of solves).
  void symbols(double qx, double qy, kernels::TangentialCoefficients& tangential,
               kernels::CouplingCoefficients& coupling) const;

 private:
  ElasticBody body1_;
  ElasticBody body2_;
  double shear_compliance_ = 0.0;
  double directional_compliance_ = 0.0;
  double coupling_compliance_ = 0.0;
  double normal_compliance_ = 0.0;  // (1 - nu1)/G1 + (1 - nu2)/G2 = 2/E*
  std::optional<LayeredMaterial> coating_;
};

}  // namespace halfspace
