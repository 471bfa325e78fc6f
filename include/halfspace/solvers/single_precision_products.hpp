// The products of a mixed-precision Polonsky-Keer iteration on
// single-precision work vectors (solver_options.hpp's Precision; the
// header of polonsky_keer.hpp, "Mixed precision"): the direction t, its
// image K t and the step's correction c are floats, so the passes over
// them move half the bytes and the transforms read and write them directly.
#pragma once

#include <functional>
#include <span>

namespace halfspace::solvers {

struct SinglePrecisionProducts {
  // out = K in (single precision; in and out may be the same array).
  std::function<void(std::span<const float>, std::span<float>)> kernel;
  // out = M^-1 in, the solver's preconditioner in single precision; empty
  // for a solver without one.
  std::function<void(std::span<const float>, std::span<float>)> precondition;
  // A field of one value per cell that the products work in (the single
  // transform's real array): free for a caller's intermediate values
  // between two products, overwritten by any product that does not write
  // into it; kernel may read it as its input and write it as its output.
  // Empty where the products have none.
  std::span<float> scratch;

  explicit operator bool() const { return static_cast<bool>(kernel); }
};

}  // namespace halfspace::solvers
