// Where MultilevelSolver's fields live on each level and how they move
// between a grid and the next coarser one. The default holds every level
// whole in this process and moves fields by grid_transfer.hpp's block
// average and constant prolongation; a distributed one (mpi/) holds this
// process's rows of the large levels and the whole of the small ones, with
// the same arithmetic.
#pragma once

#include <cstddef>
#include <span>

#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::solvers {

class LevelTransfer {
 public:
  virtual ~LevelTransfer() = default;

  // How many values of a field on `grid` this process holds.
  virtual std::size_t local_size(const Grid& grid) const { return grid.size(); }
  // The processes a field on `grid` is spread over (its sums reduce over them).
  virtual const linalg::Communicator& communicator(const Grid& /*grid*/) const { return linalg::serial_communicator(); }
  // restrict_by_average from `fine` to coarser_grid(fine), on the values held
  // here of either. Collective where the fields are distributed.
  virtual void restrict_to_coarse(const Grid& fine, std::span<const double> fine_values,
                                  std::span<double> coarse_values) {
    restrict_by_average(fine, fine_values, coarse_values);
  }
  // prolong_constant from coarser_grid(fine) to `fine`, likewise.
  virtual void prolong_to_fine(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values) {
    prolong_constant(fine, coarse_values, fine_values);
  }
};

}  // namespace halfspace::solvers
