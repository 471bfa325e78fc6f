// The law of the interface between the surfaces, beyond the elastic bodies:
// frictionless repulsion p >= 0, and optionally a hardness cap p <= H, the
// elastic-perfectly plastic surface (docs/theory.md, "Hardness cap"). It is
// physics of the material pair, not a solver knob: every solver that takes
// it solves the same bound-constrained problem.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/loading.hpp"
#include "halfspace/solvers/pressure_bounds.hpp"

namespace halfspace::solvers {

struct InterfaceLaw {
  // Indentation hardness (Pa): the pressure at which the softer surface
  // flows plastically. Unset: purely elastic contact.
  std::optional<double> hardness;

  // The physically sensible range of a hardness: from soft gels (1 kPa) to
  // above diamond (about 1e11 Pa), with room for non-dimensional studies.
  static constexpr double kMinHardness = 1e3;
  static constexpr double kMaxHardness = 1e13;

  // Throws SolverOptionError naming "hardness" unless it is unset or in
  // [kMinHardness, kMaxHardness].
  void validate() const;
  // Throws InputError naming the force, the hardness and the domain area if
  // `loading` asks for more force than the whole domain at the hardness
  // carries (load control only: the problem has no solution then).
  void check_load(const Grid& grid, const Loading& loading) const;
  // The admissible pressures: [0, H], or [0, inf) without a hardness.
  PressureBounds bounds() const;
};

// The plastic cells of a solved contact: pressure at the cap. Zero
// everywhere without a hardness.
Eigen::Array<unsigned char, Eigen::Dynamic, 1> plastic_cells(std::span<const double> pressure,
                                                             std::optional<double> hardness);
// The plastic displacement (m) of a solved contact: at the plastic cells the
// overlap max(0, -gap) of the rigid and the elastically deformed surface,
// the permanent change of the surface that unloading would leave in the
// elastic-perfectly plastic half-space model; zero elsewhere.
Eigen::ArrayXd plastic_displacement(std::span<const double> pressure, std::span<const double> gap,
                                    std::optional<double> hardness);

}  // namespace halfspace::solvers
