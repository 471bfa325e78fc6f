// What drives and bounds a lubricating film: the lubricant's viscosity, the
// surfaces' mean (entrainment) and relative (sliding) velocities, and the
// boundary of the flow domain (imposed pressures or periodic, per axis).
#pragma once

#include <array>
#include <string_view>

#include "halfspace/grid.hpp"

namespace halfspace::lubrication {

// How the film's domain ends along one axis. With fixed pressures the first
// and last nodes of the axis hold imposed pressures (the domain is
// (n - 1) spacings long); periodic wraps the last node onto the first.
enum class AxisBoundary { fixed_pressure, periodic };

std::string_view to_string(AxisBoundary boundary);

struct FlowBoundary {
  AxisBoundary x = AxisBoundary::fixed_pressure;
  double x_low_pressure = 0.0;                    // Pa, at x = 0 (the inlet when the entrainment is along +x)
  double x_high_pressure = 0.0;                   // Pa, at x = (nx - 1) dx
  AxisBoundary y = AxisBoundary::fixed_pressure;  // 2D grids only
  double y_low_pressure = 0.0;                    // Pa, at y = 0
  double y_high_pressure = 0.0;                   // Pa, at y = (ny - 1) dy
  // Fluid fraction of the lubricant at the fixed-pressure nodes: 1 is a
  // flooded supply, below 1 a starved one (Elrod–Adams' theta).
  double supply_fluid_fraction = 1.0;
};

// Steady, isoviscous, incompressible film between a rigid surface and a rigid
// flat. Velocities are (x, y) vectors in m/s: the entrainment velocity is the
// mean of the two surfaces' velocities, (u_upper + u_lower) / 2; the sliding
// velocity their difference u_upper - u_lower (it shears the film but carries
// no load in the Reynolds equation).
struct FlowConditions {
  double viscosity = 0.0;  // Pa s, > 0
  std::array<double, 2> entrainment_velocity{0.0, 0.0};
  std::array<double, 2> sliding_velocity{0.0, 0.0};
  FlowBoundary boundary;

  // Throws OptionError naming the option unless the viscosity is positive and
  // finite, the velocities and pressures finite, the pressures non-negative
  // (the cavitation pressure is 0), 0 <= supply_fluid_fraction <= 1, the y
  // velocity components 0 on a 1D grid, and some axis has fixed pressures
  // (a film periodic in every direction has no pressure level).
  void validate(const Grid& grid) const;
};

}  // namespace halfspace::lubrication
