// Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad
// 2003, alg. 9.5) on matrix-free operators: the linear solve of the EHL and
// mixed films' Newton steps (krylov_newton_step.hpp). Private to the library.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

namespace halfspace::lubrication::detail {

// How a Newton step's linear solve ended.
struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0.0;  // ||J x + r|| / ||r||, recomputed at the end with the operator
  std::string message;             // empty when converged
};

class RestartedGmres {
 public:
  // out = A v, or out = M^-1 v (out never aliases v).
  using Apply = std::function<void(const Eigen::VectorXd& v, Eigen::VectorXd& out)>;

  // Workspace for systems of `size` unknowns and a basis of `restart`
  // vectors (made once; solve allocates nothing).
  void resize(Eigen::Index size, int restart);

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

 private:
  int restart_ = 0;
  Eigen::MatrixXd basis_, hessenberg_;
  Eigen::VectorXd givens_c_, givens_s_, g_, y_, work_, preconditioned_;
};

}  // namespace halfspace::lubrication::detail
