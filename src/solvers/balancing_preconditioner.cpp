#include "halfspace/solvers/balancing_preconditioner.hpp"

#include <fmt/format.h>

#include <array>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"

namespace halfspace::solvers {

using linalg::for_each_index;
using linalg::sums;

BalancingPreconditioner::BalancingPreconditioner(InfluenceOperator& op, Preconditioner& fourier,
                                                 BlockDeflation& deflation)
    : op_(op), fourier_(fourier), deflation_(deflation) {
  if (deflation_.grid().size() != op_.grid().size() || deflation_.local_size() != op_.local_size()) {
    throw InputError("block deflation was built for a different grid than the operator's");
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
    // The kernel in real space, K e_0, for the coarse matrix.
    coarse_field_.setZero(static_cast<Eigen::Index>(n));
    if (deflation_.holds_first_cell()) coarse_field_[0] = 1.0;
    double* unit = coarse_field_.data();
    op_.apply({unit, n}, {unit, n});
    ++operator_applications_;
    deflation_.set_kernel({unit, n});
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
  apply_balancing(in, out);
  ++deflated_iterations_;
}

// B r with r = in on the search set (less its mean there under load
// control); pre_correction and post_correction are B's two halves around
// M^-1 (block_deflation.hpp).
void BalancingPreconditioner::apply_balancing(std::span<const double> in, std::span<double> out) {
  const std::size_t n = op_.local_size();
  const linalg::Communicator& comm = op_.communicator();
  const SearchSet& set = set_;
  const bool mean_free = set.mean_free;
  double* z = out.data();
  // One field holds Z y1, then its image (K in place), then K of M^-1's
  // output: post_correction needs the coarse y1 alone, which it keeps.
  double* field = coarse_field_.data();
  const auto [count, in_sum] = sums<2>(comm, n, [&](std::size_t i) {
    const double inside = set.contains(i) ? 1.0 : 0.0;
    return std::array<double, 2>{inside, inside * in[i]};
  });
  const double shift = mean_free ? in_sum / count : 0.0;
  for_each_index(n, [&](std::size_t i) { z[i] = set.contains(i) ? in[i] - shift : 0.0; });
  // values = values - minus on the set, zero elsewhere, mean-free on the set
  // under load control.
  auto onto_set = [&](double* values, const double* minus) {
    double mean = 0.0;
    if (mean_free) {
      mean = linalg::sum(comm, n,
                         [&](std::size_t i) { return set.contains(i) ? values[i] - (minus ? minus[i] : 0.0) : 0.0; }) /
             count;
    }
    for_each_index(
        n, [&](std::size_t i) { values[i] = set.contains(i) ? values[i] - (minus ? minus[i] : 0.0) - mean : 0.0; });
  };
  deflation_.pre_correction({z, n}, {field, n}, mean_free);
  op_.apply({field, n}, {field, n});
  onto_set(z, field);
  fourier_.apply({z, n}, {z, n});
  onto_set(z, nullptr);
  op_.apply({z, n}, {field, n});
  operator_applications_ += 2;
  deflation_.post_correction({field, n}, {z, n}, mean_free);
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
