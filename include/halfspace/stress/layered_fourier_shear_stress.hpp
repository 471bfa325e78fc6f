// The stress field of a coated half-space (layered_material.hpp) under a
// tangential surface traction, for one Fourier mode: the periodic grids'
// solution beside the pressure's (layered_fourier_stress.hpp), and the
// coated counterpart of fourier_shear_stress.hpp.
#pragma once

#include <array>
#include <complex>
#include <cstddef>
#include <vector>

#include "halfspace/layered_material.hpp"
#include "halfspace/stress/layered_fourier_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::stress {

// The antiplane part of a mode (the shear across k) at one depth, per unit
// traction T across k (sigma_y'z = -T on the surface): sigma_x'y' = i T
// across and sigma_y'z = -T vertical in the frame whose x' axis is k. A
// homogeneous body has across = vertical = exp(-q z).
struct AntiplaneProfile {
  double across = 0.0;
  double vertical = 0.0;
};

// The antiplane problem of the bonded layer: u_y' harmonic in each body,
// continuous u_y' and mu du_y'/dz at z = t, decaying in the substrate
// (docs/theory.md, "Stresses in a coated half-space under shear").
class LayeredAntiplane {
 public:
  // Throws InputError naming the quantity if `material` is out of range.
  explicit LayeredAntiplane(const LayeredMaterial& material);

  // mu1 q u_y'(0) / T for the mode |q| (rad/m, > 0): (1 + k e^{-2s}) /
  // (1 - k e^{-2s}), k = (mu1 - mu2)/(mu1 + mu2), s = q t; 1 for a
  // homogeneous body, mu1/mu2 for s -> 0.
  double surface_displacement(double q) const;

  // The stresses of the mode |q| (> 0) at depth z (m, >= 0) in `body`.
  AntiplaneProfile profile(double q, double z, Body body) const;

 private:
  double thickness_;
  double reflection_;           // k = (mu1 - mu2)/(mu1 + mu2)
  double transmission_;         // 1 - k = 2 mu2/(mu1 + mu2), formed without cancellation
  double substrate_stiffness_;  // mu2/mu1
};

// The multiplier of one stress component at a depth, per unit spectrum of a
// shear along x or y (`direction`; sigma_xz = -q_x, sigma_yz = -q_y on the
// surface as in surface_traction.hpp), for the wavevector (kx, ky): from the
// in-plane part of the mode (the Airy profile of LayeredFourierStress's mode
// solved with g(0) = 0, g'(0) = 1, i.e. LayeredFourierStress::solve_shear)
// and the antiplane part, both at that depth, in a body of Poisson's ratio
// nu. The mean mode (q = 0) is a uniform shear: xz = -1 (yz = -1 along y).
std::complex<double> layered_shear_stress_component(Component component, Traction direction, double kx, double ky,
                                                    const AiryProfile& longitudinal, const AntiplaneProfile& transverse,
                                                    double nu);

// All six (Component order).
std::array<std::complex<double>, kComponentCount> layered_shear_stress(Traction direction, double kx, double ky,
                                                                       const AiryProfile& longitudinal,
                                                                       const AntiplaneProfile& transverse, double nu);

// The shear multipliers of the spectrum entries a periodic grid holds here
// (SubsurfaceStress below a coating; on slabs, this process's entries):
// entry k's wavenumbers kx[k], ky[k] (rad/m), its in-plane solution solved
// once, and per depth its in-plane and antiplane profiles; about 120 bytes
// per entry.
class LayeredShearModes {
 public:
  LayeredShearModes(const LayeredMaterial& material, std::vector<double> kx, std::vector<double> ky);

  // The profiles at depth z (m) in `body`, for component().
  void evaluate(double z, Body body);
  // The multiplier of `component` under a unit shear along `direction` for
  // entry k at the last evaluated depth, nu that body's.
  std::complex<double> component(Component component, Traction direction, std::size_t k, double nu) const {
    return layered_shear_stress_component(component, direction, kx_[k], ky_[k], longitudinal_[k], transverse_[k], nu);
  }

 private:
  LayeredFourierStress modes_;
  LayeredAntiplane antiplane_;
  std::vector<double> kx_;
  std::vector<double> ky_;
  std::vector<LayeredMode> solved_;
  std::vector<AiryProfile> longitudinal_;
  std::vector<AntiplaneProfile> transverse_;
};

}  // namespace halfspace::stress
