// The influence operator K of an elastic half-space: surface displacement per
// cell pressure, u = K p. Solvers see only this interface, so the FFT
// convolution, an assembled dense matrix and a distributed operator (one slab
// of rows per process, include/halfspace/mpi/) are interchangeable.
#pragma once

#include <memory>
#include <span>

#include "halfspace/error.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/operators/circulant_form.hpp"

namespace halfspace::operators {

class SpectralTransforms;

class InfluenceOperator {
 public:
  virtual ~InfluenceOperator() = default;

  // The (whole) grid the operator acts on.
  virtual const Grid& grid() const = 0;

  // The cells of a field this process holds: all grid().size() of them, or
  // a distributed operator's slab. Fields passed to apply() and to solvers
  // built on the operator have local_size() entries.
  virtual std::size_t local_size() const { return grid().size(); }
  // The processes the field is spread over: reductions over a field (sums,
  // ranges) go through it (linalg/parallel.hpp).
  virtual const linalg::Communicator& communicator() const { return linalg::serial_communicator(); }

  // displacement = K * pressure: normal surface displacement (m, positive into
  // the half-space) for piecewise-constant cell pressures (Pa). Both spans have
  // local_size() entries and are either the same array (in place, which
  // saves a caller one field) or do not overlap. For periodic grids the mean
  // (q = 0) mode of the displacement is zero. Allocates nothing.
  virtual void apply(std::span<const double> pressure, std::span<double> displacement) = 0;

  // K_ii (m/Pa): the displacement of a cell under unit pressure on itself
  // alone. The same for every cell (the operator is translation invariant).
  virtual double self_influence() const = 0;

  // Transforms of the kind this operator multiplies on (serial, or on the
  // same processes' slabs), one transform, for another grid: those a
  // coarser operator made from this one multiplies on
  // (coarsened_influence_operator.hpp). This default: serial ones.
  // Collective.
  virtual std::unique_ptr<SpectralTransforms> transforms_for(const Grid& grid) const;

  // K as a multiplier on its transform grid (circulant_form.hpp), made on the
  // first call (its transform and the inverse symbol) and owned by the
  // operator. Throws InputError if the operator has none (this default: an
  // assembled matrix) or K has no inverse there.
  virtual CirculantForm& circulant_form() {
    throw InputError(
        "this influence operator has no circulant form (K as a multiplier on a transform grid): use the "
        "FFT operator");
  }
};

}  // namespace halfspace::operators

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using operators::CirculantForm;
using operators::InfluenceOperator;
}  // namespace halfspace
