// "LCPquad": the LCP solved as the quadratic program of the seed paper
// (Quintana Castillo, Luersen & Profito), exactly as it is written there,
//
//   minimise  z'(M z + q)   subject to  M z + q >= 0,  z >= 0,
//
// through ALGLIB's minqp dense interior-point method. On the feasible set the
// objective is z'w >= 0, so the LCP's solutions are exactly the minimisers
// with objective zero. Both for generic dense LCPs and as a contact solver.
#pragma once

#include "halfspace/solvers/dense_contact.hpp"
#include "halfspace/solvers/lcp.hpp"

namespace halfspace::solvers {

struct LcpQuadOptions {
  // ALGLIB's dense-IPM stopping tolerance: primal and dual infeasibility and
  // the complementarity gap below it (in the units of the problem). 0 lets
  // ALGLIB choose; its choice leaves pressure errors of ~1e-6 of the Hertz
  // maximum on the paper's tests, 1e-12 errors below 1e-10 (docs/paper.md).
  double tolerance = 1e-12;

  // Throws InputError naming the option unless 0 <= tolerance < 1.
  void validate() const;
};

// Solves `problem` (lcp.hpp) as the QP above. With an equality a'z = b and
// free multiplier lambda the unknowns are (z, lambda), the constraints
// M z + q - a lambda >= 0, a'z = b, z >= 0, and the objective
// z'(M z + q - a lambda) = z'M z + q'z - b lambda: still z'w, still convex.
// M + M' must be positive semidefinite (the QP is then convex). `iterations`
// counts interior-point iterations; `objective` is z'w of the returned point,
// and `message` the ALGLIB completion code when it is not a success. Throws
// InputError for an invalid problem or options. With an upper bound u (the
// box-constrained LCP of a hardness cap) the QP is instead the energy QP
// min (1/2) z'M z + q'z over 0 <= z <= u (and a'z = b), whose optimality
// conditions are the box LCP for a symmetric M (an influence matrix is);
// lambda is recovered from the cells between the bounds, and `objective` is
// the complementarity left at both bounds.
LcpSolution solve_lcp_quad(const LcpProblem& problem, const LcpQuadOptions& options = {});

// Contact solver "lcpquad": LCPquad on the contact LCP of dense_contact.hpp.
class LcpQuad final : public DenseLcpMethod<LcpQuadOptions, solve_lcp_quad> {
 public:
  LcpQuad(const Grid& grid, double e_star, LcpQuadOptions options = {}, DenseContactOptions contact = {},
          InterfaceLaw law = {})
      : DenseLcpMethod("lcpquad", grid, e_star, options, std::move(contact), law) {}
  LcpQuad(const Grid& grid, double e_star, Eigen::MatrixXd influence, LcpQuadOptions options = {},
          DenseContactOptions contact = {}, InterfaceLaw law = {})
      : DenseLcpMethod("lcpquad", grid, e_star, std::move(influence), options, std::move(contact), law) {}
};

}  // namespace halfspace::solvers
