// Lemke's complementary pivoting method (Lemke 1965; Cottle, Pang & Stone
// 1992, sec. 4.4) through Siconos Numerics (solver SICONOS_LCP_LEMKE, with
// lexicographic degeneracy resolution): for a generic dense LCP, and as a
// contact solver on the assembled influence matrix. It reports what
// Almqvist's LCPSolve reports: a solution or ray termination, and the pivots.
#pragma once

#include "halfspace/solvers/dense_contact.hpp"
#include "halfspace/solvers/lcp.hpp"

namespace halfspace::solvers {

struct LemkeOptions {
  int max_pivots = 10000;  // including the first; status iteration_limit when reached

  // Throws InputError naming the option unless max_pivots >= 1.
  void validate() const;
};

// Solves `problem` (lcp.hpp) by Lemke's method. An equality a' z = b with free
// multiplier lambda is handled by writing lambda = lambda+ - lambda-, which
// gives the (n + 2) LCP with matrix [[M, -a, a], [a', 0, 0], [-a', 0, 0]]:
// positive semidefinite when M is, so Lemke's method either solves it or ends
// on a ray, which then proves it infeasible (Cottle, Pang & Stone 1992,
// sec. 4.4). The returned w is recomputed from z. `iterations` counts the
// pivots, including the first one that brings in the covering vector (none
// when q >= 0, or for n = 1, which Siconos solves directly). Throws
// InputError for an invalid problem or options; a ray, the pivot limit or a
// returned point that does not solve the LCP is a status.
LcpSolution solve_lcp_lemke(const LcpProblem& problem, const LemkeOptions& options = {});

// Contact solver "lemke": Lemke's method on the contact LCP of
// dense_contact.hpp (displacement control: a plain LCP; load control: the
// mixed LCP with the force as an equality). Grids up to kMaxDenseCells.
class Lemke final : public DenseLcpMethod<LemkeOptions, solve_lcp_lemke> {
 public:
  Lemke(const Grid& grid, double e_star, LemkeOptions options = {}, DenseContactOptions contact = {},
        InterfaceLaw law = {})
      : DenseLcpMethod("lemke", grid, e_star, options, std::move(contact), law) {}
  Lemke(const Grid& grid, double e_star, Eigen::MatrixXd influence, LemkeOptions options = {},
        DenseContactOptions contact = {}, InterfaceLaw law = {})
      : DenseLcpMethod("lemke", grid, e_star, std::move(influence), options, std::move(contact), law) {}
};

}  // namespace halfspace::solvers
