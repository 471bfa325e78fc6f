// How a contact is loaded: by total force, by mean pressure, or by imposing
// the rigid-body approach (displacement control).
#pragma once

#include <string_view>

namespace halfspace::solvers {

enum class ControlMode {
  force,          // total normal force: N in 2D, N/m in 1D
  mean_pressure,  // force divided by the domain area (Pa)
  approach,       // rigid-body approach (m), displacement control
};

std::string_view to_string(ControlMode mode);

struct Loading {
  ControlMode mode = ControlMode::force;
  double value = 0.0;  // in the unit of `mode`

  static Loading force(double total_force) { return {ControlMode::force, total_force}; }
  static Loading mean_pressure(double pressure) { return {ControlMode::mean_pressure, pressure}; }
  static Loading approach(double distance) { return {ControlMode::approach, distance}; }

  bool load_controlled() const { return mode != ControlMode::approach; }
  // Total force (N, N/m in 1D) on a domain of `domain_area` (m^2, m in 1D)
  // under load control: the force itself, or the mean pressure times the area.
  double target_force(double domain_area) const {
    return mode == ControlMode::mean_pressure ? value * domain_area : value;
  }
  // Throws InputError naming the mode and value unless it is positive and finite.
  void validate() const;
};

// Displacement control on a periodic grid: with a zero-mean displacement the
// mean gap is mean_initial_gap - approach (m), and full contact needs an
// infinite pressure, so the approach must stay below the mean initial gap.
// Throws OptionError (option "approach", the value and the mean gap in the
// message) otherwise. The one check and wording of every solver and sweep;
// front ends restate it with their own name of the option.
void check_periodic_approach(double approach, double mean_initial_gap);

}  // namespace halfspace::solvers

// The library, its writers and front ends name these without the folder's
// namespace.
namespace halfspace {
using solvers::ControlMode;
using solvers::Loading;
using solvers::to_string;
}  // namespace halfspace
