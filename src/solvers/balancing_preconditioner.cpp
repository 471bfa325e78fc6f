#include "halfspace/solvers/balancing_preconditioner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {

using linalg::for_each_index;
using linalg::sums;

BalancingPreconditioner::BalancingPreconditioner(InfluenceOperator& op, Preconditioner& fourier,
                                                 BlockDeflation& deflation, SinglePrecisionProducts single)
    : op_(op), fourier_(fourier), deflation_(deflation), single_(std::move(single)) {
  if (deflation_.grid().size() != op_.grid().size() || deflation_.local_size() != op_.local_size()) {
    throw InputError("block deflation was built for a different grid than the operator's");
  }
  if (single_ && !single_.precondition) {
    throw InputError("the single-precision coarse correction needs the single-precision M^-1");
  }
}

template <class T>
T* BalancingPreconditioner::field() {
  const auto n = static_cast<Eigen::Index>(op_.local_size());
  if constexpr (std::is_same_v<T, float>) {
    coarse_field_.resize(0);
    // Z y1 and the images live between products only (apply_balancing).
    if (single_.scratch.size() == op_.local_size()) return single_.scratch.data();
    if (single_field_.size() != n) single_field_.setZero(n);
    return single_field_.data();
  } else {
    single_field_.resize(0);
    if (coarse_field_.size() != n) coarse_field_.setZero(n);
    return coarse_field_.data();
  }
}

void BalancingPreconditioner::begin_solve() {
  if (!continuing_) schedule_.begin_solve();
  continuing_ = false;
  active_ = false;
  operator_applications_ = 0;
  deflated_iterations_ = 0;
  stats_before_ = deflation_.stats();
}

bool BalancingPreconditioner::adapt(const SearchSet& set, std::span<const double> residuals) {
  set_ = set;
  const std::size_t n = op_.local_size();
  auto in_contact = [&](std::size_t i) { return set.in_contact(i); };  // the coarse functions' cells
  bool deflate = schedule_.wants(residuals);
  if (deflate && !kernel_known_ && deflation_.decline_if_dense(in_contact)) {
    deflate = false;  // too dense a contact: not in this solve, and no kernel or field made for it
    schedule_.decline();
  }
  if (deflate && !kernel_known_) {
    // The kernel in real space, K e_0, for the coarse matrix (in the
    // precision of the work vectors, in the correction's field).
    if (single_) {
      float* unit = field<float>();
      std::fill(unit, unit + n, 0.0F);
      if (deflation_.holds_first_cell()) unit[0] = 1.0F;
      single_.kernel({unit, n}, {unit, n});
      deflation_.set_kernel(std::span<const float>(unit, n));
    } else {
      double* unit = field<double>();
      std::fill(unit, unit + n, 0.0);
      if (deflation_.holds_first_cell()) unit[0] = 1.0;
      op_.apply({unit, n}, {unit, n});
      deflation_.set_kernel(std::span<const double>(unit, n));
    }
    ++operator_applications_;
    kernel_known_ = true;
  }
  if (deflate) {
    deflation_.update(in_contact);
    if (!deflation_.ready()) schedule_.decline();  // too dense a contact: not in this solve
    deflate = deflation_.ready();
  }
  const bool changed = deflate != active_;
  active_ = deflate;
  return changed;
}

void BalancingPreconditioner::observe_step(const StepReport& step) {
  schedule_.observe_step(active_, step.clipped, step.searched);
}

void BalancingPreconditioner::apply(std::span<const double> in, std::span<double> out) {
  if (!active_) {
    fourier_.apply(in, out);
    return;
  }
  apply_balancing<double>(in, out);
  ++deflated_iterations_;
}

void BalancingPreconditioner::apply_single(std::span<const float> in, std::span<float> out) {
  if (!single_) throw std::logic_error("BalancingPreconditioner::apply_single without single-precision products");
  if (!active_) {
    single_.precondition(in, out);
    return;
  }
  apply_balancing<float>(in, out);
  ++deflated_iterations_;
}

// B r with r = in on the search set (less its mean there under load
// control); pre_correction and post_correction are B's two halves around
// M^-1 (block_deflation.hpp).
template <class T>
void BalancingPreconditioner::apply_balancing(std::span<const T> in, std::span<T> out) {
  const std::size_t n = op_.local_size();
  const linalg::Communicator& comm = op_.communicator();
  const SearchSet& set = set_;
  const bool mean_free = set.mean_free;
  T* z = out.data();
  // One field holds Z y1, then its image (K in place), then K of M^-1's
  // output: post_correction needs the coarse y1 alone, which it keeps.
  T* coarse = field<T>();
  auto kernel = [&](const T* from, T* to) {
    if constexpr (std::is_same_v<T, float>) {
      single_.kernel({from, n}, {to, n});
    } else {
      op_.apply({from, n}, {to, n});
    }
  };
  const auto [count, in_sum] = sums<2>(comm, n, [&](std::size_t i) {
    const double inside = set.contains(i) ? 1.0 : 0.0;
    return std::array<double, 2>{inside, inside * static_cast<double>(in[i])};
  });
  const double shift = mean_free ? in_sum / count : 0.0;
  for_each_index(n, [&](std::size_t i) { z[i] = static_cast<T>(set.contains(i) ? in[i] - shift : 0.0); });
  // values = values - minus on the set, zero elsewhere, mean-free on the set
  // under load control (the mean summed in double).
  auto onto_set = [&](T* values, const T* minus) {
    double mean = 0.0;
    if (mean_free) {
      mean = linalg::sum(comm, n,
                         [&](std::size_t i) -> double {
                           return set.contains(i) ? static_cast<double>(values[i]) - (minus ? minus[i] : 0.0) : 0.0;
                         }) /
             count;
    }
    for_each_index(n, [&](std::size_t i) {
      values[i] = static_cast<T>(set.contains(i) ? values[i] - (minus ? minus[i] : 0.0) - mean : 0.0);
    });
  };
  deflation_.pre_correction(std::span<const T>(z, n), std::span<T>(coarse, n), mean_free);
  kernel(coarse, coarse);
  onto_set(z, coarse);
  if constexpr (std::is_same_v<T, float>) {
    single_.precondition({z, n}, {z, n});
  } else {
    fourier_.apply({z, n}, {z, n});
  }
  onto_set(z, nullptr);
  kernel(z, coarse);
  operator_applications_ += 2;
  deflation_.post_correction(std::span<const T>(coarse, n), std::span<T>(z, n), mean_free);
}

void BalancingPreconditioner::report(SolveResult& result) const {
  const BlockDeflationStats& after = deflation_.stats();
  result.operator_applications += operator_applications_;
  result.deflation.block = deflation_.block();
  result.deflation.deflated_iterations = deflated_iterations_;
  result.deflation.rebuilds = after.rebuilds - stats_before_.rebuilds;
  result.deflation.updates = after.updates - stats_before_.updates;
  result.deflation.declined = after.declined - stats_before_.declined;
  result.deflation.coarse_iterations = after.coarse_iterations - stats_before_.coarse_iterations;
  result.deflation.unconverged_coarse_solves =
      after.unconverged_coarse_solves - stats_before_.unconverged_coarse_solves;
  result.deflation.fast_rate = schedule_.fast_rate();
  if (result.deflation.unconverged_coarse_solves > 0) {
    result.warnings.push_back(
        fmt::format("block deflation: {} of {} coarse solves stopped short of their tolerance (iteration limit or "
                    "non-positive curvature), so the coarse correction was inexact",
                    result.deflation.unconverged_coarse_solves, 2 * result.deflation.deflated_iterations));
  }
}

}  // namespace halfspace::solvers
