// Restarted, right-preconditioned GMRES (restarted_gmres.hpp): Arnoldi by
// modified Gram-Schmidt, the Hessenberg matrix reduced by Givens rotations
// as it grows, so that |g_{j+1}| is the residual norm of the current iterate;
// and a Newton step's solve with it.
#include "restarted_gmres.hpp"

#include <fmt/format.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <memory>
#include <new>
#include <utility>

#include "halfspace/linalg/parallel.hpp"

namespace halfspace::lubrication::detail {

double* ArnoldiStorage::reserve(std::size_t values) {
  if (values > capacity_) {
    data_.reset();  // the old pages go before the new ones come
    data_ = std::make_unique_for_overwrite<double[]>(values);
    capacity_ = values;
  }
  return data_.get();
}

void RestartedGmres::resize(Eigen::Index size, int restart, ArnoldiStorage* storage) {
  restart_ = restart;
  ArnoldiStorage& held = storage != nullptr ? *storage : own_basis_;
  // Re-seating a Map (Eigen's documented placement new).
  new (&basis_)
      Eigen::Map<Eigen::MatrixXd>(held.reserve(static_cast<std::size_t>(size) * (restart + 1)), size, restart + 1);
  hessenberg_.resize(restart + 1, restart);
  givens_c_.resize(restart);
  givens_s_.resize(restart);
  g_.resize(restart + 1);
  y_.resize(restart);
  work_.resize(size);
  preconditioned_.resize(size);
}

void RestartedGmres::distribute(KrylovDistribution distribution, Eigen::Index replicated) {
  distribution_ = std::move(distribution);
  replicated_ = replicated;
}

double RestartedGmres::dot(Eigen::Ref<const Eigen::VectorXd> a, Eigen::Ref<const Eigen::VectorXd> b) const {
  if (!distribution_.spread()) return a.dot(b);
  const Eigen::Index own = a.size() - replicated_;
  return distribution_.sum(a.head(own).dot(b.head(own))) + a.tail(replicated_).dot(b.tail(replicated_));
}

double RestartedGmres::norm(Eigen::Ref<const Eigen::VectorXd> v) const {
  return distribution_.spread() ? std::sqrt(dot(v, v)) : v.norm();
}

bool RestartedGmres::all_finite(const Eigen::VectorXd& v) const {
  return distribution_.spread() ? distribution_.all(v.allFinite()) : v.allFinite();
}

int RestartedGmres::solve(const Apply& apply, const Apply& precondition, const Eigen::VectorXd& residual,
                          double tolerance, int max_iterations, Eigen::VectorXd& x, bool warm) {
  int iterations = 0;
  const double b_norm = norm(residual);
  if (!warm || b_norm == 0.0 || x.size() != residual.size() || !all_finite(x)) x.setZero(residual.size());
  if (b_norm == 0.0) return 0;
  while (iterations < max_iterations) {
    apply(x, work_);
    work_ = -residual - work_;
    const double beta = norm(work_);
    if (beta <= tolerance * b_norm) break;
    basis_.col(0) = work_ / beta;
    g_.setZero();
    g_[0] = beta;
    int size = 0;
    for (int j = 0; j < restart_ && iterations < max_iterations; ++j) {
      work_ = basis_.col(j);
      precondition(work_, preconditioned_);
      apply(preconditioned_, work_);
      for (int i = 0; i <= j; ++i) {
        hessenberg_(i, j) = dot(basis_.col(i), work_);
        work_ -= hessenberg_(i, j) * basis_.col(i);
      }
      const double length = norm(work_);
      hessenberg_(j + 1, j) = length;
      if (length > 0.0) basis_.col(j + 1) = work_ / length;
      for (int i = 0; i < j; ++i) {
        const double upper = hessenberg_(i, j), lower = hessenberg_(i + 1, j);
        hessenberg_(i, j) = givens_c_[i] * upper + givens_s_[i] * lower;
        hessenberg_(i + 1, j) = givens_c_[i] * lower - givens_s_[i] * upper;
      }
      const double radius = std::hypot(hessenberg_(j, j), hessenberg_(j + 1, j));
      givens_c_[j] = radius > 0.0 ? hessenberg_(j, j) / radius : 1.0;
      givens_s_[j] = radius > 0.0 ? hessenberg_(j + 1, j) / radius : 0.0;
      hessenberg_(j, j) = radius;
      hessenberg_(j + 1, j) = 0.0;
      g_[j + 1] = -givens_s_[j] * g_[j];
      g_[j] *= givens_c_[j];
      ++iterations;
      size = j + 1;
      if (std::abs(g_[j + 1]) <= tolerance * b_norm || length == 0.0) break;
    }
    y_.head(size) = g_.head(size);
    hessenberg_.topLeftCorner(size, size).triangularView<Eigen::Upper>().solveInPlace(y_.head(size));
    work_.noalias() = basis_.leftCols(size) * y_.head(size);
    precondition(work_, preconditioned_);
    x += preconditioned_;
    if (!all_finite(x)) break;
  }
  return iterations;
}

void KrylovNewtonStep::setup(Eigen::Index size, Eigen::Index sparse_rows, int restart, Apply inverse,
                             ArnoldiStorage* storage) {
  gmres_.resize(size, restart, storage);
  inverse_ = std::move(inverse);
  bordered_ = size == sparse_rows + 1;
  for (Eigen::VectorXd* v : {&border_column, &load_row, &border_solved_, &head_in_, &head_out_}) v->resize(sparse_rows);
  work_.resize(size);
}

void KrylovNewtonStep::distribute(KrylovDistribution distribution) {
  distribution_ = distribution;
  gmres_.distribute(std::move(distribution), bordered_ ? 1 : 0);
}

bool KrylovNewtonStep::factorise_border(const char* singular, std::string& message) {
  inverse_(border_column, border_solved_);
  border_pivot_ = sum(load_row.dot(border_solved_));
  if (std::isfinite(border_pivot_) && border_pivot_ != 0.0) return true;
  message = singular;
  return false;
}

void KrylovNewtonStep::precondition(const Eigen::VectorXd& v, Eigen::VectorXd& out) {
  if (!bordered_) return inverse_(v, out);
  const Eigen::Index n = head_in_.size();
  linalg::for_each_index(static_cast<std::size_t>(n), [&](std::size_t k) {
    head_in_[static_cast<Eigen::Index>(k)] = v[static_cast<Eigen::Index>(k)];
  });
  inverse_(head_in_, head_out_);
  const double z = (sum(load_row.dot(head_out_)) - v[n]) / border_pivot_;
  out.resize(n + 1);
  linalg::for_each_index(static_cast<std::size_t>(n), [&](std::size_t k) {
    const auto kk = static_cast<Eigen::Index>(k);
    out[kk] = head_out_[kk] - z * border_solved_[kk];
  });
  out[n] = z;
}

KrylovOutcome KrylovNewtonStep::solve(const Apply& jacobian, const std::function<bool(std::string&)>& factorise,
                                      const Eigen::VectorXd& residual, int max_iterations, const Rule& rule,
                                      Eigen::VectorXd& step) {
  const Apply preconditioner = [this](const Eigen::VectorXd& v, Eigen::VectorXd& out) { precondition(v, out); };
  KrylovOutcome outcome;
  const LaggedPreconditioner::Run run = lagged_.solve(
      rule.refactorise, max_iterations, [&] { return factorise(outcome.message); },
      [&](int iterations_allowed, bool retry) {
        const bool warm = rule.warm || (retry && rule.retry_warm);
        const int iterations =
            gmres_.solve(jacobian, preconditioner, residual, rule.tolerance, iterations_allowed, step, warm);
        return std::pair{iterations, gmres_.all_finite(step)};
      });
  outcome.iterations = run.iterations;
  if (!run.factorised) {
    outcome.relative_residual = std::numeric_limits<double>::infinity();  // no step at all
    return outcome;
  }
  // The residual measured with the operator, not GMRES's estimate.
  jacobian(step, work_);
  work_ += residual;
  const double b_norm = gmres_.norm(residual);
  outcome.relative_residual = b_norm > 0.0 ? gmres_.norm(work_) / b_norm : 0.0;
  outcome.converged = gmres_.all_finite(step) && outcome.relative_residual <= rule.allowance * rule.tolerance;
  if (!outcome.converged) {
    outcome.message =
        fmt::format(fmt::runtime(rule.failure), outcome.relative_residual, outcome.iterations, rule.tolerance);
  }
  return outcome;
}

}  // namespace halfspace::lubrication::detail
