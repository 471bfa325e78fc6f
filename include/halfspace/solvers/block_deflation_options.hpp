// The options of BlockDeflation (block_deflation.hpp): the block size and
// the limits of its coarse work. SolverOptions reaches them through
// DeflationOptions (solver_options.hpp).
#pragma once

#include <cstddef>

namespace halfspace::solvers {

struct BlockDeflationOptions {
  std::size_t block = 32;  // cells per block side; must divide nx and ny
  // The most pair-sum terms per cell a full build of A may take: a few
  // hundred on sparse rough contacts, thousands on nearly full ones, where
  // the preconditioner alone needs few iterations anyway (docs/solvers.md).
  double max_pair_terms = 1000.0;
  double coarse_tolerance = 1e-8;
  int coarse_max_iterations = 1000;

  // Throws SolverOptionError naming the option ("deflation.block", ...)
  // unless 1 <= block <= 256, max_pair_terms > 0, 0 < coarse_tolerance < 1
  // and coarse_max_iterations >= 1.
  void validate() const;
};

}  // namespace halfspace::solvers
