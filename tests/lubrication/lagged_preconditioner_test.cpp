// The film GMRES's reuse of work between linear solves
// (src/lubrication/restarted_gmres.hpp): a solve
// warm-started from a nearby system's solution, and a preconditioner
// factorised for an earlier matrix, reach the tolerance on the new system
// (measured here with the dense matrix, not GMRES's estimate); the stale
// preconditioner is replaced when GMRES cannot converge quickly with it.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <limits>
#include <random>
#include <utility>

#include "lubrication/restarted_gmres.hpp"

namespace halfspace::lubrication::detail {
namespace {

// A nonsymmetric, diagonally dominant matrix with an upwind-like band and
// random far entries: GMRES with a Jacobi preconditioner needs tens of
// iterations on it.
Eigen::MatrixXd model_matrix(Eigen::Index n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, i) = 4.0 + uniform(random);
    if (i > 0) a(i, i - 1) = -2.5;
    if (i + 1 < n) a(i, i + 1) = -0.5;
    for (int k = 0; k < 4; ++k) a(i, static_cast<Eigen::Index>((i * 7 + k * 13 + 5) % n)) += 0.2 * uniform(random);
  }
  return a;
}

Eigen::VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = uniform(random);
  return v;
}

double relative_residual(const Eigen::MatrixXd& a, const Eigen::VectorXd& x, const Eigen::VectorXd& residual) {
  return (a * x + residual).norm() / residual.norm();
}

TEST(LaggedPreconditionerTest, WarmStartedGmresReachesTheToleranceInFewerIterations) {
  constexpr Eigen::Index n = 300;
  constexpr double tolerance = 1e-9;
  const Eigen::MatrixXd a = model_matrix(n, 1);
  const Eigen::VectorXd inverse_diagonal = a.diagonal().cwiseInverse();
  RestartedGmres gmres;
  gmres.resize(n, 40);
  const auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out.noalias() = a * v; };
  const auto jacobi = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out = inverse_diagonal.cwiseProduct(v); };
  const Eigen::VectorXd residual = random_vector(n, 2);
  Eigen::VectorXd x(n);
  const int cold = gmres.solve(apply, jacobi, residual, tolerance, 1000, x);
  EXPECT_LE(relative_residual(a, x, residual), 10.0 * tolerance);
  // A nearby right-hand side (a branch pass changes a few rows).
  Eigen::VectorXd nearby = residual;
  for (Eigen::Index i = 100; i < 104; ++i) nearby[i] += 0.5;
  Eigen::VectorXd from_cold(n);
  const int again_cold = gmres.solve(apply, jacobi, nearby, tolerance, 1000, from_cold);
  const int warm = gmres.solve(apply, jacobi, nearby, tolerance, 1000, x, true);
  EXPECT_LE(relative_residual(a, x, nearby), 10.0 * tolerance);
  EXPECT_LE((x - from_cold).norm(), 1e-7 * from_cold.norm());
  EXPECT_GT(cold, 10);
  EXPECT_LT(warm, again_cold);
  // A warm start from a vector that is not finite starts from 0.
  x.setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(gmres.solve(apply, jacobi, nearby, tolerance, 1000, x, true), again_cold);
  EXPECT_LE(relative_residual(a, x, nearby), 10.0 * tolerance);
}

TEST(LaggedPreconditionerTest, StaleFactorisationServesNearbyMatricesAndIsReplacedOtherwise) {
  constexpr Eigen::Index n = 300;
  constexpr double tolerance = 1e-9;
  constexpr int max_iterations = 400;
  Eigen::MatrixXd a = model_matrix(n, 3);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  RestartedGmres gmres;
  gmres.resize(n, 40);
  LaggedPreconditioner lagged;
  const Eigen::VectorXd residual = random_vector(n, 4);
  Eigen::VectorXd x(n);
  const auto solve = [&] {
    return lagged.solve(
        false, max_iterations,
        [&] {
          lu.compute(a);
          return true;
        },
        [&](int limit, bool) {
          const int iterations =
              gmres.solve([&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out.noalias() = a * v; },
                          [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out = lu.solve(v); }, residual,
                          tolerance, limit, x);
          return std::pair{iterations, x.allFinite()};
        });
  };
  // The first solve factorises; with the exact inverse GMRES takes 1 product.
  LaggedPreconditioner::Run run = solve();
  EXPECT_EQ(run.factorisations, 1);
  EXPECT_LE(run.iterations, 2);
  EXPECT_LE(relative_residual(a, x, residual), 10.0 * tolerance);
  // Three rows change (contact rows opening): the old factors serve.
  for (Eigen::Index i : {10, 150, 290}) a.row(i) *= 3.0;
  run = solve();
  EXPECT_EQ(run.factorisations, 0);
  EXPECT_LT(run.iterations, 2 * LaggedPreconditioner::kRefactoriseAfter);
  EXPECT_LE(relative_residual(a, x, residual), 10.0 * tolerance);
  // Every row changes: GMRES with the old factors gives up after twice
  // kRefactoriseAfter products, the matrix is factorised again and solved.
  a = model_matrix(n, 5);
  a.diagonal().array() *= Eigen::ArrayXd::LinSpaced(n, 0.2, 5.0);
  run = solve();
  EXPECT_EQ(run.factorisations, 1);
  EXPECT_GE(run.iterations, 2 * LaggedPreconditioner::kRefactoriseAfter);
  EXPECT_LE(relative_residual(a, x, residual), 10.0 * tolerance);
  // A factorisation that fails is reported, not used.
  const LaggedPreconditioner::Run failed = lagged.solve(
      true, max_iterations, [] { return false; },
      [&](int, bool) {
        return std::pair{0, true};
      });
  EXPECT_FALSE(failed.factorised);
}

}  // namespace
}  // namespace halfspace::lubrication::detail
