// The wedge whose dry contact sits on its outlet node, where the pressure is
// imposed: the inclined slider touching at its trailing edge. The EHL and
// mixed films must both start from it (their dry start carries the load on
// that node alone) and, nearly rigid, give the inclined slider's load.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"

namespace halfspace::testing {

struct OutletTouchingWedge {
  static constexpr std::size_t nodes = 161;
  static constexpr double length = 4e-4;     // m
  static constexpr double rise = 1e-5;       // gap at the inlet, 0 at the outlet (m)
  static constexpr double viscosity = 0.04;  // Pa s
  static constexpr double velocity = 1.0;    // entrainment along x (m/s)

  Grid grid = Grid::line(nodes, length / static_cast<double>(nodes - 1), Boundary::free);
  Eigen::ArrayXd gap = [] {
    Eigen::ArrayXd g(static_cast<Eigen::Index>(nodes));
    for (std::size_t i = 0; i < nodes; ++i) {
      g[static_cast<Eigen::Index>(i)] = rise * (1.0 - static_cast<double>(i) / static_cast<double>(nodes - 1));
    }
    return g;
  }();
  lubrication::FlowConditions conditions = [] {
    lubrication::FlowConditions c;
    c.viscosity = viscosity;
    c.entrainment_velocity = {velocity, 0.0};
    return c;
  }();

  // The inclined slider h = h_o (1 + k (1 - x / L)) carries W' = 12 eta u L^2
  // / (h_o^2 k^2) (ln(1 + k) - 2 k / (2 + k)) per length (Hamrock, Schmid &
  // Jacobson 2004, ch. 8, u the mean velocity); here at the solved film's
  // outlet thickness and inclination.
  double slider_load(const Eigen::ArrayXd& film) const {
    const double ho = film[film.size() - 1];
    const double k = (film[0] - ho) / ho;
    return 12.0 * viscosity * velocity * length * length / (ho * ho * k * k) *
           (std::log(1.0 + k) - 2.0 * k / (2.0 + k));
  }
};

}  // namespace halfspace::testing
