// Where a solve's fields live and which operators act on them: the whole
// grid on this process (serial_layout(): one slab holding every row), or
// this process's slab of rows of a grid spread over MPI processes
// (mpi/distributed_layout.hpp). make_solver builds every solver type on the
// operators a layout makes, so each is written once for both.
#pragma once

#include <cstddef>
#include <memory>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/fft/fft_planning.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/half_space.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/preconditioner.hpp"
#include "halfspace/solvers/single_precision_products.hpp"

namespace halfspace::solvers {

class LevelTransfer;  // level_transfer.hpp (the engine's, not installed)

struct SolverOptions;

// An influence operator and, if asked for, the Fourier preconditioner made
// with it (they may share a transform or a buffer: the operator lives as
// long as the preconditioner).
struct ElasticOperators {
  std::unique_ptr<InfluenceOperator> op;
  std::unique_ptr<Preconditioner> fourier;  // null unless asked for
  // Mixed precision: K in single precision for the step's products (null
  // where they stay double); it acts on op's fields and may share its
  // buffers, so the two never run at once.
  std::unique_ptr<InfluenceOperator> inner;
  // Mixed precision where this layout has them: inner's K and fourier's
  // M^-1 on single-precision vectors (they reference the two above).
  SinglePrecisionProducts single;
};

// This process's rows of a grid: [first, first + count).
struct RowSlab {
  std::size_t first = 0;
  std::size_t count = 0;
};

class Layout {
 public:
  virtual ~Layout() = default;

  // The transforms of `grid`'s fields as this layout holds them (periodic:
  // the grid's own; free: the zero-padded DC-FFT pair, or the grid's own
  // if `shape.unpadded`), on which every operator below multiplies its
  // symbols, and code with symbols of its own too (the subsurface
  // stresses). Collective.
  virtual std::unique_ptr<operators::SpectralTransforms> make_transforms(
      const Grid& grid, FftPlanning planning, const operators::TransformsShape& shape = {}) const = 0;
  // The operator u = K p of `half_space` on `grid` (FftInfluenceOperator
  // on make_transforms), with `planning` for its transforms, and with
  // `fourier` the Fourier preconditioner (FourierPreconditioner). Periodic
  // grids: the two share the transform (Polonsky-Keer applies them one
  // after the other), M^-1 the inverse of K's symbol (no symbol of its
  // own). Free grids: the preconditioner's unpadded transform works in the
  // operator's padded buffer, idle between products (16 B per cell less).
  // Collective; throws as the operators do.
  ElasticOperators make_operators(const Grid& grid, const HalfSpace& half_space, bool fourier,
                                  FftPlanning planning) const;
  // The tangential compliance (and the normal-tangential coupling) of
  // `pair` on `grid` for fields held as this layout holds them, for the
  // frictional solve. Collective; throws as the operator does.
  std::unique_ptr<TangentialOperator> make_tangential_operator(const Grid& grid, const ElasticPair& pair,
                                                               FftPlanning planning) const;
  // The same for a mixed-precision solve (solver_options.hpp's Precision):
  // the operator in double, and where this layout can, the Fourier
  // preconditioner and `inner` in single precision. This default (a layout
  // that solves in double only) throws SolverOptionError naming the option
  // "precision".
  virtual ElasticOperators make_mixed_operators(const Grid& grid, const HalfSpace& half_space, bool fourier,
                                                FftPlanning planning) const;
  // The rows of `grid` this process holds (a 1D grid: its one row).
  virtual RowSlab rows(const Grid& grid) const = 0;
  // The processes a field is spread over.
  virtual const linalg::Communicator& communicator() const = 0;
  // Throws SolverOptionError naming the option and what to use instead
  // unless this layout solves `options` on `grid` for `half_space` (called
  // by make_solver after options.validate).
  virtual void check(const Grid& /*grid*/, const HalfSpace& /*half_space*/, const SolverOptions& /*options*/) const {}
  // Where pk-multilevel's levels of `fine` live: null, all whole here (the
  // MultilevelSolver's default). Collective.
  virtual std::unique_ptr<LevelTransfer> level_transfer(const Grid& fine, std::size_t min_cells_per_axis) const;
  // The layout of `level`, one of the levels of `transfer` (made by
  // level_transfer).
  virtual const Layout& level_layout(const LevelTransfer& /*transfer*/, const Grid& /*level*/) const { return *this; }
};

// The whole grid on this process: the serial transforms
// (operators::make_serial_transforms), one slab holding every row.
const Layout& serial_layout();
// The same for a small grid solved whole on every process of a distributed
// solve (a gathered multilevel level): estimated plans, whatever the
// options say, since measured ones may differ between processes and so
// round differently.
const Layout& redundant_layout();

}  // namespace halfspace::solvers
