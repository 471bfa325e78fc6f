// The finite-volume discretisation of the steady Reynolds equation with the
// fluid fraction theta in the Couette term (Elrod–Adams' p–theta form):
//
//   div( h^3 / (12 eta) grad p ) = div( U h theta ),
//
// on the grid's nodes, each the centre of a control volume whose faces lie
// half-way to its neighbours (vertex-centred finite volumes; Patankar 1980).
// Per unit area of the control volume of an unknown node P the mass balance reads
//
//   A_P p_P - sum_nb a_nb p_nb + B_P h_P theta_P - sum_up b_up h_up theta_up = 0,
//
// with face conductances a = h_f^3 / (12 eta d^2) (h_f the mean of the two
// nodes' films), A_P their sum, the Couette flux upwinded (b = |U_x| / dx,
// |U_y| / dy from the node upstream; B_P = |U_x| / dx + |U_y| / dy).
// The transient equation adds d(h theta)/dt to the balance as
// c h_P theta_P - s_P (set_time_term; transient_film.hpp).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"

namespace halfspace::lubrication {

// Neighbours of a node; kNone where there is none (past a fixed-pressure edge).
struct Neighbours {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t west = kNone, east = kNone, south = kNone, north = kNone;
};

class ReynoldsStencil {
 public:
  // `film` holds h > 0 (m) on every node of `grid`; `conditions` must have
  // been validated for `grid`. Throws InputError if a film value is not
  // positive and finite.
  ReynoldsStencil(const Grid& grid, const Eigen::ArrayXd& film, const FlowConditions& conditions);

  const Grid& grid() const { return grid_; }
  const Eigen::ArrayXd& film() const { return film_; }
  const FlowConditions& conditions() const { return conditions_; }
  std::size_t size() const { return film_.size(); }

  // Whether node k holds an imposed pressure (an edge of a fixed-pressure axis).
  bool fixed(std::size_t k) const { return fixed_[k] != 0; }
  // The imposed pressure and fluid fraction of a fixed node.
  double fixed_pressure(std::size_t k) const { return fixed_pressure_[k]; }
  Neighbours neighbours(std::size_t k) const;

  // Face conductances h_f^3 / (12 eta) / d^2 (1/(Pa s) * m): of the face
  // east of node k (between k and its east neighbour) and north of it; 0
  // where there is no neighbour.
  double east_conductance(std::size_t k) const { return east_[k]; }
  double north_conductance(std::size_t k) const { return north_[k]; }
  // |U_x| / dx and |U_y| / dy (1/s; 0 on a 1D grid's y).
  double couette_x() const { return couette_x_; }
  double couette_y() const { return couette_y_; }
  // The upstream neighbour of node k along x and y (kNone without flow).
  std::size_t upstream_x(const Neighbours& n) const {
    return conditions_.entrainment_velocity[0] >= 0 ? n.west : n.east;
  }
  std::size_t upstream_y(const Neighbours& n) const {
    return conditions_.entrainment_velocity[1] >= 0 ? n.south : n.north;
  }

  // The mass balance of node k's control volume (m/s): outflow minus inflow
  // per unit area, the left-hand side above; 0 for a fixed node.
  double mass_balance(std::size_t k, const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) const;
  // The volume flow through the face east of node k (m^3/s in 2D, m^2/s per
  // unit width in 1D), positive along +x; and north of it, along +y.
  double east_flow(std::size_t k, const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) const;
  double north_flow(std::size_t k, const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) const;

  // A flux density that sets the scale of the mass balance (m/s): the
  // largest Couette outflow B_P h_P, or without entrainment the largest
  // Poiseuille outflow A_P p_P of `pressure`.
  double balance_scale(const Eigen::ArrayXd& pressure) const;

  // The time term of the transient equation: d(h theta)/dt at node k as
  // rate * h_k theta_k - stored_k (1/s; m/s), a backward difference whose
  // previous steps make `stored` (transient_film.hpp). rate 0 (the default)
  // is the steady equation. Throws InputError unless rate >= 0 and finite
  // and `stored` is finite, >= 0 and one value a node.
  void set_time_term(double rate, Eigen::ArrayXd stored);
  double time_rate() const { return time_rate_; }
  double stored(std::size_t k) const { return time_rate_ > 0.0 ? stored_[k] : 0.0; }

 private:
  Grid grid_;
  Eigen::ArrayXd film_;
  FlowConditions conditions_;
  std::vector<unsigned char> fixed_;
  Eigen::ArrayXd fixed_pressure_;
  Eigen::ArrayXd east_;
  Eigen::ArrayXd north_;
  double couette_x_ = 0.0;
  double couette_y_ = 0.0;
  double time_rate_ = 0.0;
  Eigen::ArrayXd stored_;
};

}  // namespace halfspace::lubrication
