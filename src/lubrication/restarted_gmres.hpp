// Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad
// 2003, alg. 9.5) on matrix-free operators, and the linear solve of the EHL
// and mixed films' Newton steps with it (KrylovNewtonStep). Private to the
// library.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace halfspace::lubrication::detail {

// How a Newton step's linear solve ended.
struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0.0;  // ||J x + r|| / ||r||, recomputed at the end with the operator
  std::string message;             // empty when converged
};

// How a solve's vectors are spread over processes (film_slab.hpp): each
// holds its own entries of B's rows, followed by the `replicated` entries
// every process holds alike (the border's h0), counted once; `sum` adds a
// value over the processes and `all` agrees on a condition. Unset (one
// process): Eigen's products as they are.
struct KrylovDistribution {
  std::function<double(double)> sum;
  std::function<bool(bool)> all;

  bool spread() const { return static_cast<bool>(sum); }
};

// Storage for a GMRES basis that outlives one solver: the mixed film makes
// a solver per Newton solve, and a basis made afresh each time (up to 1.7 GB
// at 1024^2) is paged in afresh, one page fault per 4 kB on first touch; on
// the measured window at 1024^2 the kernel's zeroing of those pages was
// 6.5 % of a profile's samples (docs/development-log.md, 2026-12-04,
// forty-fifth session). It grows to the largest basis asked for and leaves
// its values uninitialised.
class ArnoldiStorage {
 public:
  // At least `values` doubles, their contents unspecified.
  double* reserve(std::size_t values);

 private:
  std::unique_ptr<double[]> data_;
  std::size_t capacity_ = 0;
};

class RestartedGmres {
 public:
  // out = A v, or out = M^-1 v (out never aliases v).
  using Apply = std::function<void(const Eigen::VectorXd& v, Eigen::VectorXd& out)>;

  // Not copied or moved: basis_ views storage, and a Map's assignment
  // copies values instead of re-seating the view.
  RestartedGmres() = default;
  RestartedGmres(const RestartedGmres&) = delete;
  RestartedGmres& operator=(const RestartedGmres&) = delete;

  // Workspace for systems of `size` unknowns and a basis of `restart`
  // vectors (made once; solve allocates nothing), the basis in `storage`
  // where given (which must outlive the solver's solves), else its own.
  void resize(Eigen::Index size, int restart, ArnoldiStorage* storage = nullptr);

  // Solves A x = -residual (the Newton step of `residual`) from x = 0 (or,
  // with `warm`, from the x given: a branch pass's step from the last
  // pass's, which differs from it in a few rows), with
  // A M^-1 y = -residual, x = M^-1 y, until GMRES's own estimate of
  // ||A x + residual|| (the Givens-rotated least-squares residual, no product
  // needed) is at most tolerance ||residual||, or `max_iterations` products
  // have been taken, or x stops being finite. Returns the products taken; the
  // caller measures the true residual.
  int solve(const Apply& apply, const Apply& precondition, const Eigen::VectorXd& residual, double tolerance,
            int max_iterations, Eigen::VectorXd& x, bool warm = false);

  // Vectors spread over processes, the last `replicated` entries on every
  // one (set before solve; the serial products otherwise).
  void distribute(KrylovDistribution distribution, Eigen::Index replicated);
  // The inner product, norm and finiteness of the solve's vectors as the
  // distribution has them.
  double dot(Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b) const;
  double norm(Eigen::Ref<const Eigen::VectorXd> v) const;
  bool all_finite(const Eigen::VectorXd& v) const;

 private:
  KrylovDistribution distribution_;
  Eigen::Index replicated_ = 0;
  int restart_ = 0;
  ArnoldiStorage own_basis_;
  // size x (restart + 1), in own_basis_ or the storage lent to resize.
  Eigen::Map<Eigen::MatrixXd> basis_{nullptr, 0, 0};
  Eigen::MatrixXd hessenberg_;
  Eigen::VectorXd givens_c_, givens_s_, g_, y_, work_, preconditioned_;
};

// A Newton iteration's preconditioner kept from one linear solve to the
// next (a lagged preconditioner; Knoll & Keyes 2004, J. Comput. Phys. 193,
// 357): an earlier factorisation serves while GMRES converges with it in
// few iterations, as the Jacobian changes little between late Newton steps
// and between a step's branch passes (a few rows). Refactorised when the
// caller asks (`refactorise`), when the last solve took more than
// kRefactoriseAfter iterations, or when GMRES with the old one does not
// converge within twice that (then solved again with the new one).
class LaggedPreconditioner {
 public:
  static constexpr int kRefactoriseAfter = 15;

  struct Run {
    bool factorised = true;  // false: `factorise` failed (its message is the caller's)
    int iterations = 0;      // GMRES products, every attempt
    int factorisations = 0;
  };

  // `factorise()` returns whether it succeeded; `gmres(max_iterations,
  // retry)` solves (retry: the second attempt, with a new factorisation)
  // and returns {iterations, whether its step is finite}.
  template <class Factorise, class Gmres>
  Run solve(bool refactorise, int max_iterations, Factorise&& factorise, Gmres&& gmres) {
    Run run;
    bool fresh = false;
    if (!factorised_ || refactorise || last_iterations_ > kRefactoriseAfter) {
      factorised_ = factorise();
      ++run.factorisations;
      if (!factorised_) return {false, 0, run.factorisations};
      fresh = true;
    }
    const int stale_limit = std::min(max_iterations, 2 * kRefactoriseAfter);
    auto [iterations, finite] = gmres(fresh ? max_iterations : stale_limit, false);
    run.iterations = iterations;
    if (!fresh && !(finite && iterations < stale_limit)) {
      factorised_ = factorise();
      ++run.factorisations;
      if (!factorised_) return {false, run.iterations, run.factorisations};
      iterations = gmres(max_iterations, true).first;
      run.iterations += iterations;
    }
    last_iterations_ = iterations;
    return run;
  }

 private:
  bool factorised_ = false;
  int last_iterations_ = 0;
};

// A Newton step's linear solve J step = -residual: GMRES right-preconditioned
// by a lagged preconditioner, the residual then measured with the operator.
// The preconditioner is the caller's approximate inverse M ~ B^-1 of the
// Jacobian's sparse part B, bordered under load control by the h0 column c
// and the load row l, [B c; l^T 0], whose inverse is applied by the Schur
// complement: z = (l^T M f - g) / (l^T M c), y = M f - z M c. What the EHL
// and mixed films' solves differ in is a Rule.
class KrylovNewtonStep {
 public:
  using Apply = RestartedGmres::Apply;
  struct Rule {
    double tolerance = 0.0;    // on GMRES's estimate of ||J step + residual|| / ||residual||
    double allowance = 1.0;    // converged when the measured residual is at most allowance * tolerance
    bool refactorise = false;  // the kept preconditioner no longer fits the system
    bool warm = false;         // from `step` as given, else from 0
    bool retry_warm = false;   // the retry after a stale preconditioner goes on from where it stopped
    const char* failure = "";  // fmt message: {0} the measured residual, {1} the iterations, {2} the tolerance
  };

  // Systems of `size` unknowns, B of `sparse_rows` rows (bordered when
  // size = sparse_rows + 1), a GMRES(restart) basis (in `storage` where
  // given, RestartedGmres::resize) and M (`inverse`).
  void setup(Eigen::Index size, Eigen::Index sparse_rows, int restart, Apply inverse,
             ArnoldiStorage* storage = nullptr);

  // c and l, the caller's to set before factorise_border.
  Eigen::VectorXd border_column, load_row;
  // M c, once M is factorised; false with the message `singular` when
  // l^T M c is 0 or not finite.
  bool factorise_border(const char* singular, std::string& message);

  // The solve's vectors spread over processes, the border (if any) on every
  // one (RestartedGmres::distribute).
  void distribute(KrylovDistribution distribution);

  // Solves J step = -residual within `max_iterations` products per attempt;
  // `factorise(message)` makes M (and the border). Returns the
  // factorisation's failure (relative residual infinite) or GMRES's.
  KrylovOutcome solve(const Apply& jacobian, const std::function<bool(std::string&)>& factorise,
                      const Eigen::VectorXd& residual, int max_iterations, const Rule& rule, Eigen::VectorXd& step);

 private:
  void precondition(const Eigen::VectorXd& v, Eigen::VectorXd& out);

  // Sums B's rows' inner products over the processes.
  double sum(double local) const { return distribution_.spread() ? distribution_.sum(local) : local; }

  RestartedGmres gmres_;
  KrylovDistribution distribution_;
  LaggedPreconditioner lagged_;
  Apply inverse_;
  bool bordered_ = false;
  Eigen::VectorXd work_, border_solved_, head_in_, head_out_;
  double border_pivot_ = 0.0;
};

}  // namespace halfspace::lubrication::detail
