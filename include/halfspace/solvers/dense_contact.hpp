// Contact problems on an assembled influence matrix, posed as a dense LCP in
// non-dimensional units: the part the Lemke and LCPquad solvers share.
//
// Units. Influence coefficients in SI are about 1e-16 m/Pa, far below any
// pivot or interior-point tolerance, so the LCP handed to a method is
// non-dimensional: lengths in a unit L, pressures in a unit P, and gaps and
// displacements in the matching unit u = P L / E*. Then
//
//   M = K E* / L,   z = p / P,   w = gap / u,
//
// every entry is O(1), and two inputs that differ only in their units (SI,
// or lengths in Hertz half-widths and pressures in Hertz maxima) give the
// same LCP and the same pressures. With the Hertz half-width and maximum as
// L and P these are the Hertz units of the line contact.
//
// Load control. The force is imposed as an equality and the approach is its
// free multiplier (a mixed LCP):
//
//   w = M z + q - 1 delta >= 0,  z >= 0,  z' w = 0,  1' z = W / (A_cell P),
//
// with q = g0 / u. It is the optimality system of the minimum of the
// complementary energy (1/2) z' M z + q' z over z >= 0 with the load fixed,
// so for a positive semidefinite K it has a solution, which Lemke's method
// finds in one run, with the force exact to rounding; a root search on the
// approach would need one LCP solve per step and meets the force only to its
// tolerance. Displacement control is the plain LCP with q = (g0 - delta)/u.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/contact_solver.hpp"
#include "halfspace/solvers/lcp.hpp"

namespace halfspace::solvers {

// Internal units; zero means "choose automatically".
struct DenseUnits {
  double length = 0.0;    // L (m); automatic: the cell size, sqrt(dx dy) in 2D
  double pressure = 0.0;  // P (Pa); automatic: the mean pressure W / domain area under load control, the
                          // local-overlap pressure max(delta - g0) / K_ii under displacement control
};

struct DenseContactOptions {
  DenseUnits units;
  // false hands the SI problem to the LCP method unchanged. Only for showing
  // what that does (docs/paper.md); never needed otherwise.
  bool nondimensionalise = true;
  // The result counts as converged when the method succeeded and the contact
  // residual (the Polonsky-Keer stopping measure) is at most this.
  double tolerance = 1e-10;

  // Throws InputError naming the option unless 0 < tolerance < 1 and the
  // units are finite and >= 0.
  void validate() const;
};

// The LCP of a contact problem and the units that lead back to SI.
struct ContactLcp {
  LcpProblem lcp;
  double length_unit = 1.0;    // L (m)
  double pressure_unit = 1.0;  // P (Pa)
  double gap_unit = 1.0;       // u = P L / E* (m)
};

// Poses the contact problem (influence matrix K in m/Pa, initial gap g0 in m,
// loading) as the LCP above; a hardness cap p <= H in `law` makes it the
// box-constrained one, z <= H / P (LcpProblem::upper_bound). Throws
// InputError for invalid loading or sizes.
ContactLcp make_contact_lcp(const Grid& grid, double e_star, const Eigen::MatrixXd& influence,
                            std::span<const double> initial_gap, const Loading& loading,
                            const DenseContactOptions& options, const InterfaceLaw& law = {});

// The Polonsky-Keer stopping measure of a contact state (polonsky_keer.hpp):
// ( sum_i (p_i / pbar) |g_i| + sum_i max(-g_i, 0) ) / (N g_ref), with
// g_ref = ptp(g0) + max(ptp(K p), pbar uniform_response_range), where
// uniform_response_range = ptp(K 1), so that dense and FFT results compare.
// With a hardness H the capped form of polonsky_keer.hpp: the positive part
// of g in the first sum, the overlap weighed by (H - p_i)/H in the second.
double contact_residual(std::span<const double> initial_gap, const Eigen::ArrayXd& pressure,
                        const Eigen::ArrayXd& displacement, const Eigen::ArrayXd& gap, double uniform_response_range,
                        std::optional<double> hardness = std::nullopt);

// A contact solver that assembles K and solves the contact LCP with a dense
// method (the derived class). Warm starts are ignored: the methods are direct
// (Lemke) or start from their own interior point (LCPquad).
class DenseContactSolver : public ContactSolver {
 public:
  // `name` is the solver's name (results, messages). Assembles K for `grid`;
  // throws InputError naming the grid size and pointing to the FFT solver if
  // it exceeds kMaxDenseCells.
  DenseContactSolver(std::string_view name, const Grid& grid, double e_star, DenseContactOptions options,
                     const InterfaceLaw& law = {});
  // Uses a given n x n matrix (m/Pa), n = grid.size(), e.g. another kernel.
  DenseContactSolver(std::string_view name, const Grid& grid, double e_star, Eigen::MatrixXd influence,
                     DenseContactOptions options, const InterfaceLaw& law = {});

  std::string_view name() const final { return name_; }

  const Grid& grid() const { return grid_; }
  // The method's own report on the last solve (pivots, ray termination, QP
  // objective), in internal units.
  const LcpSolution& last_solution() const { return last_solution_; }

 protected:
  SolveResult do_solve(std::span<const double> initial_gap, const Loading& loading,
                       std::span<const double> initial_pressure) final;
  virtual LcpSolution solve_lcp(const LcpProblem& problem) = 0;

 private:
  std::string name_;
  Grid grid_;
  double e_star_;
  Eigen::MatrixXd influence_;
  DenseContactOptions options_;
  ContactLcp last_lcp_;
  LcpSolution last_solution_;
};

// A dense contact solver whose LCP method is `Method` with its options
// (Lemke, LcpQuad): the options validated after the base's checks.
template <class MethodOptions, LcpSolution (*Method)(const LcpProblem&, const MethodOptions&)>
class DenseLcpMethod : public DenseContactSolver {
 protected:
  DenseLcpMethod(std::string_view name, const Grid& grid, double e_star, MethodOptions options,
                 DenseContactOptions contact, const InterfaceLaw& law)
      : DenseContactSolver(name, grid, e_star, std::move(contact), law), options_(validated(std::move(options))) {}
  DenseLcpMethod(std::string_view name, const Grid& grid, double e_star, Eigen::MatrixXd influence,
                 MethodOptions options, DenseContactOptions contact, const InterfaceLaw& law)
      : DenseContactSolver(name, grid, e_star, std::move(influence), std::move(contact), law),
        options_(validated(std::move(options))) {}

 private:
  static MethodOptions validated(MethodOptions options) {
    options.validate();
    return options;
  }
  LcpSolution solve_lcp(const LcpProblem& problem) final { return Method(problem, options_); }

  MethodOptions options_;
};

// Throws InputError unless the dense matrix of `grid` fits (kMaxDenseCells),
// with a message naming the solver, the grid size and the FFT alternative.
void check_dense_grid(const Grid& grid, std::string_view solver);

}  // namespace halfspace::solvers
