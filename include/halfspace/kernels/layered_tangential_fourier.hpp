// The periodic tangential and normal-tangential compliance of a coated
// half-space (an elastic layer of thickness t bonded to an elastic substrate,
// layered_material.hpp) against a rigid surface, per Fourier mode, in the
// conventions of tangential_fourier.hpp and coupling_fourier.hpp (the coated
// body is body 1, the rigid surface body 2). In the axes of the wave vector
// the mode splits into a plane-strain problem along q (pressure and the
// longitudinal shear, the Airy mode of stress/layered_fourier_stress.hpp) and
// an antiplane one (the transverse shear, u_y = A e^{qz} + B e^{-qz} in the
// layer, decaying in the substrate): docs/theory.md, "Tangential compliance
// of a coated half-space" (O'Sullivan & King 1988).
#pragma once

#include "halfspace/kernels/coupling_coefficients.hpp"
#include "halfspace/kernels/tangential_coefficients.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/stress/layered_fourier_shear_stress.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"

namespace halfspace::kernels {

// The four surface compliances of one mode times |q| (1/Pa): a homogeneous
// body of shear modulus G and Poisson's ratio nu has normal = longitudinal =
// (1 - nu)/G, transverse = 1/G, coupling = (1 - 2 nu)/G.
struct LayeredModeCompliance {
  double normal = 0.0;        // u_n per p: 2 M(q t)/E1* (layered_fourier.hpp)
  double longitudinal = 0.0;  // u along q per shear along q
  double transverse = 0.0;    // u across q per shear across q
  // D_eff of coupling_fourier.hpp: the tangential displacement along q per
  // pressure is -i D_eff/(2 q) (from the pressure's mode)...
  double coupling = 0.0;
  // ...and the normal displacement per shear along q is +i D_eff/(2 q): this
  // one from the shear's mode, equal to `coupling` by Betti's reciprocity.
  double coupling_transpose = 0.0;
};

class LayeredTangentialKernel {
 public:
  // Throws InputError naming the quantity if `material` is out of range.
  explicit LayeredTangentialKernel(const LayeredMaterial& material);

  const LayeredMaterial& material() const { return modes_.material(); }

  // The compliances of the mode |q| (rad/m, > 0); two small solves.
  LayeredModeCompliance mode_compliance(double q) const;
  // The 2x2 tangential symbol at (qx, qy) (tangential_fourier.hpp's form,
  // shear = transverse, directional = transverse - longitudinal); zero at q = 0.
  TangentialCoefficients tangential(double qx, double qy) const;
  // The coupling symbol c at (qx, qy) (coupling_fourier.hpp with D_eff);
  // zero at q = 0.
  CouplingCoefficients coupling(double qx, double qy) const;
  // Both at once (one pair of solves).
  void symbols(double qx, double qy, TangentialCoefficients& tangential, CouplingCoefficients& coupling) const;

  // Free grids (docs/theory.md, "Tangential compliance of a coated
  // half-space"): the symbols less their closed-form part, which is the
  // layer's Cerruti and coupling kernels plus the substrate's less the
  // layer's smoothed to `height` h (m; cerruti_rectangle.hpp,
  // coupling_rectangle.hpp, their `height`). The rest is finite at q = 0 and
  // decays like exp(-q t); summed over the alias images times the cell's
  // transform (for_each_alias_image, layered_fourier.hpp) it is the DFT at
  // (qx, qy) of its cell coefficients on a grid of spacing (dx, dy). The
  // q = 0 image takes the mean over directions of its limit there.
  void remainder_cell_spectrum(double qx, double qy, double dx, double dy, double height,
                               TangentialCoefficients& tangential, CouplingCoefficients& coupling) const;

 private:
  // The remainder's three factors times q (1/Pa), the forms of
  // tangential_spectrum (shear, directional) and coupling_spectrum.
  struct Factors {
    double shear = 0.0;
    double directional = 0.0;
    double coupling = 0.0;
  };
  Factors remainder(double q, double height) const;
  Factors layer_;      // a homogeneous body's 1/G, nu/G, (1 - 2 nu)/G: the layer's
  Factors substrate_;  // and the substrate's
  stress::LayeredFourierStress modes_;
  stress::LayeredAntiplane antiplane_;
  double layer_shear_modulus_;  // mu1, Pa
};

}  // namespace halfspace::kernels
