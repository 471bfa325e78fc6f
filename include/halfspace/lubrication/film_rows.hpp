// The rows of a film that one process holds, seen by the cavitation solver:
// its stencil covers these rows and one halo row on each side that another
// process owns (held as fixed nodes, so that the sweeps pass over them),
// and this object brings the halo rows' values between the sweeps and
// reduces the convergence measures over every process. The halo rows hold
// what the serial sweep would read there (the neighbour's row after this
// sweep if the serial sweep passes it first, after the previous sweep
// otherwise), so that the rows' solution is the serial one, iterate by
// iterate. Without it (nullptr) the stencil is the whole film: serial is the
// one-slab case. mpi/slab_film_rows.hpp is the MPI implementation.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>

#include "halfspace/grid.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"

namespace halfspace::lubrication {

class FilmRows {
 public:
  virtual ~FilmRows() = default;
  // The whole film's grid (it sets the automatic relaxation factor).
  virtual const Grid& whole_grid() const = 0;
  // Once, after the solver has set its starting values: sends this
  // process's boundary rows.
  virtual void start(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) = 0;
  // Before and after each sweep: fills the halo rows the sweep reads, then
  // sends the boundary rows it changed.
  virtual void before_sweep(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) = 0;
  virtual void after_sweep(const Eigen::ArrayXd& pressure, const Eigen::ArrayXd& fluid_fraction) = 0;
  // Before the convergence is measured: both halo rows as they are now.
  virtual void complete(Eigen::ArrayXd& pressure, Eigen::ArrayXd& fluid_fraction) = 0;
  // The largest of `value` and whether `value` holds on every process.
  virtual double max(double value) const = 0;
  virtual bool all(bool value) const = 0;

  // What the film's pipeline (load_control.hpp, film_forces.hpp,
  // film_shear.hpp) needs beyond the sweeps. The stencil's grid and
  // conditions: this process's rows and its halo rows, which are
  // fixed-pressure edges there.
  virtual const Grid& stencil_grid() const = 0;
  virtual const FlowConditions& stencil_conditions() const = 0;
  // A field on the stencil's rows from this process's rows of it (the halo
  // rows from the neighbours). Collective.
  virtual Eigen::ArrayXd stencil_field(std::span<const double> rows) const = 0;
  // This process's nodes of the stencil: first_own_node() .. + own_nodes() - 1.
  virtual std::size_t first_own_node() const = 0;
  virtual std::size_t own_nodes() const = 0;
  // Whether stencil node k holds an imposed pressure of the whole film (a
  // halo row is fixed in the stencil only so that the sweeps pass over it).
  virtual bool fixed_in_whole(std::size_t k) const = 0;
  // values[i] summed over the processes (in rank order: the same bits on
  // every process), and the smallest of `value`.
  virtual void sum(std::span<double> values) const = 0;
  virtual double min(double value) const = 0;
};

}  // namespace halfspace::lubrication
