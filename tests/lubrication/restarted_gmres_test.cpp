// The film GMRES (src/lubrication/restarted_gmres.hpp) on its own: the
// solve must reach its tolerance measured with the operator (not GMRES's
// estimate), on a system large enough for linalg's threads, with the same
// bits on one thread and two.
#include "lubrication/restarted_gmres.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "halfspace/threads.hpp"

namespace halfspace::lubrication::detail {
namespace {

// A lower bidiagonal operator, (A v)_i = d_i v_i - s v_{i-1}, d_i from
// `lowest` to `highest` along the rows: non-normal (as the Reynolds rows'
// upwind Couette terms make the film's), its eigenvalues the d_i.
struct Bidiagonal {
  Eigen::Index n;
  double lowest, highest, s;

  double d(Eigen::Index i) const {
    return lowest + (highest - lowest) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  void operator()(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
    for (Eigen::Index i = 0; i < n; ++i) out[i] = d(i) * v[i] - (i > 0 ? s * v[i - 1] : 0.0);
  }
};

Eigen::VectorXd smooth_load(Eigen::Index n) {
  Eigen::VectorXd r(n);
  for (Eigen::Index i = 0; i < n; ++i) r[i] = std::sin(0.001 * static_cast<double>(i)) + 0.5;
  return r;
}

double measured_residual(const Bidiagonal& a, const Eigen::VectorXd& x, const Eigen::VectorXd& residual) {
  Eigen::VectorXd ax(a.n);
  a(x, ax);
  return (ax + residual).norm() / residual.norm();
}

// 60 000 unknowns (above linalg's threshold for threads), Jacobi-
// preconditioned GMRES(30): converged to 1e-8 as measured, and the same
// bits with one thread and with two.
TEST(RestartedGmresTest, ReachesTheToleranceWithTheSameBitsOnAnyThreads) {
  constexpr Eigen::Index n = 60000;
  constexpr double tolerance = 1e-8;
  const Bidiagonal a{n, 1.0, 3.0, 0.8};
  const auto jacobi = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    for (Eigen::Index i = 0; i < n; ++i) out[i] = v[i] / a.d(i);
  };
  const Eigen::VectorXd residual = smooth_load(n);
  const int original = threads();
  Eigen::VectorXd x1(n), x2(n);
  RestartedGmres gmres;
  gmres.resize(n, 30);
  set_threads(1);
  const int iterations1 = gmres.solve(a, jacobi, residual, tolerance, 1000, x1);
  set_threads(2);
  const int iterations2 = gmres.solve(a, jacobi, residual, tolerance, 1000, x2);
  set_threads(original);
  EXPECT_LT(iterations1, 1000);
  EXPECT_LE(measured_residual(a, x1, residual), 10.0 * tolerance);
  EXPECT_EQ(iterations1, iterations2);
  EXPECT_EQ((x1 - x2).cwiseAbs().maxCoeff(), 0.0);
}

// A basis in lent storage (ArnoldiStorage, kept across solvers as the mixed
// film keeps it across its Newton solves): the same iterates as the
// solver's own basis, storage left dirty by a larger solve, and the storage
// not made anew for a basis it holds.
TEST(RestartedGmresTest, LentBasisStorageGivesTheSameIterates) {
  constexpr double tolerance = 1e-8;
  const auto solve = [&](Eigen::Index n, ArnoldiStorage* storage, Eigen::VectorXd& x) {
    const Bidiagonal a{n, 1.0, 3.0, 0.8};
    const auto jacobi = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
      for (Eigen::Index i = 0; i < n; ++i) out[i] = v[i] / a.d(i);
    };
    RestartedGmres gmres;
    gmres.resize(n, 30, storage);
    const int iterations = gmres.solve(a, jacobi, smooth_load(n), tolerance, 1000, x);
    EXPECT_LE(measured_residual(a, x, smooth_load(n)), 10.0 * tolerance);
    return iterations;
  };
  ArnoldiStorage storage;
  Eigen::VectorXd own_large(4000), lent_large(4000), own_small(1000), lent_small(1000);
  const int own_large_its = solve(4000, nullptr, own_large);
  EXPECT_EQ(solve(4000, &storage, lent_large), own_large_its);
  EXPECT_EQ((own_large - lent_large).cwiseAbs().maxCoeff(), 0.0);
  const double* large_basis = storage.reserve(1);
  const int own_small_its = solve(1000, nullptr, own_small);
  EXPECT_EQ(solve(1000, &storage, lent_small), own_small_its);
  EXPECT_EQ((own_small - lent_small).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(storage.reserve(4000 * 31), large_basis);
}

}  // namespace
}  // namespace halfspace::lubrication::detail
