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

#include "halfspace/grid.hpp"

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
};

}  // namespace halfspace::lubrication
