// A preconditioner for contact solvers: an approximation of the inverse of
// the influence operator, z = M^-1 r, applied to residuals (gaps).
#pragma once

#include <span>

namespace halfspace::solvers {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // out = M^-1 in, both with one entry per cell; `out` may be `in` itself
  // (in place). M^-1 must be symmetric positive definite. Allocates nothing.
  virtual void apply(std::span<const double> in, std::span<double> out) = 0;
};

}  // namespace halfspace::solvers
