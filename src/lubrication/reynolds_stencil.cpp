// Vertex-centred finite volumes for the p–theta Reynolds equation: each face
// carries a Poiseuille flux from the pressure difference over a conductance
// built from the face's film (the mean of its two nodes, second order on
// smooth films) and an upwinded Couette flux U h theta, so that what leaves
// one control volume enters the next and the scheme conserves mass exactly
// (Patankar 1980, ch. 4; Profito, Giacopini, Zachariadis & Dini 2015,
// Tribol. Lett. 60:18). Upwinding keeps the Couette term of the cavitated
// zone (pure transport of h theta) monotone.
#include "halfspace/lubrication/reynolds_stencil.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

ReynoldsStencil::ReynoldsStencil(const Grid& grid, const Eigen::ArrayXd& film, const FlowConditions& conditions)
    : grid_(grid), film_(film), conditions_(conditions) {
  const std::size_t n = grid.size();
  if (static_cast<std::size_t>(film.size()) != n) {
    throw InputError(fmt::format("film has {} values, the {} grid has {} nodes", film.size(), grid.shape_string(), n));
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!(std::isfinite(film[k]) && film[k] > 0.0)) {
      throw InputError(
          fmt::format("film thickness {} m at node (x {}, y {}) is invalid: the film must be positive "
                      "and finite everywhere (increase the separation)",
                      film[k], k % grid.nx(), k / grid.nx()));
    }
  }
  const std::size_t nx = grid.nx();
  const std::size_t ny = grid.ny();
  const bool two_d = grid.dimension() == 2;
  const FlowBoundary& b = conditions.boundary;
  fixed_.assign(n, 0);
  fixed_pressure_ = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t k = j * nx + i;
      if (two_d && b.y == AxisBoundary::fixed_pressure && (j == 0 || j == ny - 1)) {
        fixed_[k] = 1;
        fixed_pressure_[k] = j == 0 ? b.y_low_pressure : b.y_high_pressure;
      }
      if (b.x == AxisBoundary::fixed_pressure && (i == 0 || i == nx - 1)) {
        fixed_[k] = 1;
        fixed_pressure_[k] = i == 0 ? b.x_low_pressure : b.x_high_pressure;
      }
    }
  }
  const double poiseuille = 1.0 / (12.0 * conditions.viscosity);
  east_ = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  north_ = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k) {
    const Neighbours nb = neighbours(k);
    if (nb.east != Neighbours::kNone) {
      const double h = 0.5 * (film_[k] + film_[nb.east]);
      east_[k] = poiseuille * h * h * h / (grid.dx() * grid.dx());
    }
    if (nb.north != Neighbours::kNone) {
      const double h = 0.5 * (film_[k] + film_[nb.north]);
      north_[k] = poiseuille * h * h * h / (grid.dy() * grid.dy());
    }
  }
  couette_x_ = std::abs(conditions.entrainment_velocity[0]) / grid.dx();
  couette_y_ = two_d ? std::abs(conditions.entrainment_velocity[1]) / grid.dy() : 0.0;
}

Neighbours ReynoldsStencil::neighbours(std::size_t k) const {
  const std::size_t nx = grid_.nx();
  const std::size_t ny = grid_.ny();
  const std::size_t i = k % nx;
  const std::size_t j = k / nx;
  const bool periodic_x = conditions_.boundary.x == AxisBoundary::periodic;
  Neighbours n;
  if (i > 0) {
    n.west = k - 1;
  } else if (periodic_x) {
    n.west = k + nx - 1;
  }
  if (i + 1 < nx) {
    n.east = k + 1;
  } else if (periodic_x) {
    n.east = k + 1 - nx;
  }
  if (grid_.dimension() == 2) {
    const bool periodic_y = conditions_.boundary.y == AxisBoundary::periodic;
    if (j > 0) {
      n.south = k - nx;
    } else if (periodic_y) {
      n.south = k + (ny - 1) * nx;
    }
    if (j + 1 < ny) {
      n.north = k + nx;
    } else if (periodic_y) {
      n.north = k - (ny - 1) * nx;
    }
  }
  return n;
}

double ReynoldsStencil::mass_balance(std::size_t k, const Eigen::ArrayXd& pressure,
                                     const Eigen::ArrayXd& fluid_fraction) const {
  if (fixed(k)) return 0.0;
  const Neighbours nb = neighbours(k);
  double poiseuille = 0.0;
  const auto face = [&](std::size_t other, double conductance) {
    if (other != Neighbours::kNone) poiseuille += conductance * (pressure[k] - pressure[other]);
  };
  face(nb.west, nb.west != Neighbours::kNone ? east_[nb.west] : 0.0);
  face(nb.east, east_[k]);
  face(nb.south, nb.south != Neighbours::kNone ? north_[nb.south] : 0.0);
  face(nb.north, north_[k]);
  double couette = (couette_x_ + couette_y_) * film_[k] * fluid_fraction[k];
  const std::size_t up_x = upstream_x(nb);
  const std::size_t up_y = upstream_y(nb);
  if (up_x != Neighbours::kNone) couette -= couette_x_ * film_[up_x] * fluid_fraction[up_x];
  if (up_y != Neighbours::kNone) couette -= couette_y_ * film_[up_y] * fluid_fraction[up_y];
  if (time_rate_ > 0.0) couette += time_rate_ * film_[k] * fluid_fraction[k] - stored_[k];
  return poiseuille + couette;
}

double ReynoldsStencil::east_flow(std::size_t k, const Eigen::ArrayXd& pressure,
                                  const Eigen::ArrayXd& fluid_fraction) const {
  const std::size_t east = neighbours(k).east;
  if (east == Neighbours::kNone) return 0.0;
  const double u = conditions_.entrainment_velocity[0];
  const std::size_t up = u >= 0.0 ? k : east;
  const double per_width = -east_[k] * grid_.dx() * (pressure[east] - pressure[k]) + u * film_[up] * fluid_fraction[up];
  return grid_.dimension() == 2 ? per_width * grid_.dy() : per_width;
}

double ReynoldsStencil::north_flow(std::size_t k, const Eigen::ArrayXd& pressure,
                                   const Eigen::ArrayXd& fluid_fraction) const {
  const std::size_t north = neighbours(k).north;
  if (north == Neighbours::kNone) return 0.0;
  const double v = conditions_.entrainment_velocity[1];
  const std::size_t up = v >= 0.0 ? k : north;
  return (-north_[k] * grid_.dy() * (pressure[north] - pressure[k]) + v * film_[up] * fluid_fraction[up]) * grid_.dx();
}

double ReynoldsStencil::balance_scale(const Eigen::ArrayXd& pressure) const {
  double couette = 0.0;
  double poiseuille = 0.0;
  for (std::size_t k = 0; k < size(); ++k) {
    if (fixed(k)) continue;
    couette = std::max(couette, (couette_x_ + couette_y_) * film_[k]);
    const Neighbours nb = neighbours(k);
    double conductance = east_[k] + north_[k];
    if (nb.west != Neighbours::kNone) conductance += east_[nb.west];
    if (nb.south != Neighbours::kNone) conductance += north_[nb.south];
    poiseuille = std::max(poiseuille, conductance * std::abs(pressure[k]));
  }
  // The time term's storage rate * h joins the Couette scale (the transient
  // balance is a difference of such terms); the steady scale is unchanged.
  const double storage = time_rate_ * film_.maxCoeff();
  const double scale = storage > 0.0 ? std::max(couette + storage, poiseuille) : couette > 0.0 ? couette : poiseuille;
  return scale > 0.0 ? scale : std::numeric_limits<double>::min();
}

void ReynoldsStencil::set_time_term(double rate, Eigen::ArrayXd stored) {
  if (!(std::isfinite(rate) && rate >= 0.0)) {
    throw InputError(fmt::format("time term rate {} 1/s is invalid: it must be >= 0 and finite", rate));
  }
  if (static_cast<std::size_t>(stored.size()) != size() || !stored.allFinite() || (stored < 0.0).any()) {
    throw InputError(fmt::format("time term: the stored fluid needs {} finite values >= 0 (one a node), got {}", size(),
                                 stored.size()));
  }
  time_rate_ = rate;
  stored_ = std::move(stored);
}

}  // namespace halfspace::lubrication
