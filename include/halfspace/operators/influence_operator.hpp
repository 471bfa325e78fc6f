// The influence operator K of an elastic half-space: surface displacement per
// cell pressure, u = K p. Solvers see only this interface, so the FFT
// convolution and an assembled dense matrix are interchangeable.
#pragma once

#include <span>

#include "halfspace/grid.hpp"

namespace halfspace::operators {

class InfluenceOperator {
 public:
  virtual ~InfluenceOperator() = default;

  // The grid the operator acts on; fields have grid().size() entries.
  virtual const Grid& grid() const = 0;

  // displacement = K * pressure: normal surface displacement (m, positive into
  // the half-space) for piecewise-constant cell pressures (Pa). Both spans have
  // grid().size() entries and are either the same array (in place, which
  // saves a caller one field) or do not overlap. For periodic grids the mean
  // (q = 0) mode of the displacement is zero. Allocates nothing.
  virtual void apply(std::span<const double> pressure, std::span<double> displacement) = 0;

  // K_ii (m/Pa): the displacement of a cell under unit pressure on itself
  // alone. The same for every cell (the operator is translation invariant).
  virtual double self_influence() const = 0;
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::InfluenceOperator;
}  // namespace halfspace
