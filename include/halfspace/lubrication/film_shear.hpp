// The shear stress a solved film exerts on its lower surface, and the
// friction (traction) it sums to. Across the film the velocity profile of
// Reynolds' equation gives, on the lower surface,
//
//   tau = tau_c - (h / 2) grad p,    tau_c = theta eta(p) (u_upper - u_lower) / h,
//
// the Couette part from the sliding velocity, carried by the fluid fraction
// theta of the gap (striated cavitated film), and the Poiseuille part from
// the pressure gradient. In an EHL contact eta(p) grows by orders of
// magnitude and the Newtonian Couette stress exceeds what a lubricant can
// carry: the optional limits bound it, on its magnitude along the sliding
// direction,
//
//   Eyring (1936):                tau_c = tau0 asinh(tau_N / tau0)
//   limiting shear stress:        |tau_c| <= tau_L0 + gamma p
//                                 (Bair & Winer 1979; gamma as Evans & Johnson 1986)
//
// with tau_N the Newtonian stress. Both may apply (Eyring, then the cap).
// The film (pressure and h) stays the Newtonian Reynolds solution: the
// limits enter the traction only, as traction calculations decoupled from
// the film do (the film is set in the inlet, where the shear stresses are
// low; Evans & Johnson 1986, Proc. IMechE C 200, 313).
#pragma once

#include <Eigen/Core>
#include <array>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/lubrication/lubricant.hpp"

namespace halfspace::lubrication {

struct ShearLimits {
  double eyring_stress = 0.0;          // tau0 (Pa); 0: no Eyring law
  double limiting_shear_stress = 0.0;  // tau_L0 (Pa); both 0: no cap
  double limiting_shear_slope = 0.0;   // gamma (-), the cap's growth with pressure

  bool eyring() const { return eyring_stress > 0.0; }
  bool capped() const { return limiting_shear_stress > 0.0 || limiting_shear_slope > 0.0; }

  // Throws OptionError naming the option unless every value is >= 0 and
  // finite.
  void validate() const;
};

struct FilmShear {
  // Pa, (ny, nx) row-major on the film's nodes: tau on the lower surface,
  // its x and y components.
  Eigen::ArrayXd shear_x, shear_y;
  // N (N/m in 1D): the shear integrated over the domain by the trapezoidal
  // rule (half weights on fixed-pressure edge nodes, as film_forces), and
  // its Couette part.
  std::array<double, 2> friction_force{0.0, 0.0};
  std::array<double, 2> couette_force{0.0, 0.0};
  double load = 0.0;                  // the pressure integrated alike (N, N/m in 1D)
  double friction_coefficient = 0.0;  // |friction_force| / load (0 without load)
  // Nodes whose Couette stress a limit lowered by more than 1%, over all nodes.
  double limited_fraction = 0.0;
};

// The shear of the film h (m) with pressure p (Pa) and fluid fraction theta
// on `grid` under `conditions` (its viscosity, sliding velocity and flow
// boundary), with the viscosity law of `laws`. Validates the conditions,
// the laws and the limits; throws InputError for arrays of the wrong size
// or a film that is not positive. Nodes where `contact_pressure` (if given)
// is positive carry no film shear: a mixed film's asperities take them
// (their friction is the caller's). With `rows` (film_rows.hpp), `grid`
// and `conditions` are its stencil's and the fields its nodes' (halo rows
// included): the shear fields cover this process's rows, the forces the
// whole film (sums over the processes, equal to the serial ones to
// rounding). Collective then.
FilmShear film_shear(const Grid& grid, const FlowConditions& conditions, const LubricantLaws& laws,
                     const ShearLimits& limits, const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                     const Eigen::ArrayXd& fluid_fraction, const Eigen::ArrayXd* contact_pressure = nullptr,
                     const FilmRows* rows = nullptr);

}  // namespace halfspace::lubrication
