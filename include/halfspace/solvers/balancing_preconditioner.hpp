// The Fourier preconditioner with the block-deflation coarse correction in
// balancing form (Mandel 1993; Tang, Nabben, Vuik & Erlangga 2009):
//
//   B r = Q r + (I - Q K) M^-1 (I - K Q) r,   Q = Z A^-1 Z^T,
//
// with M^-1 the Fourier preconditioner, K the influence operator and Z, A
// the coarse space of block_deflation.hpp on the contact cells. B acts on
// the search set (under load control on its mean-free fields, where the
// iteration moves, so that it stays symmetric there). A DeflationSchedule
// decides in which iterations the correction applies; in the others B is
// M^-1 alone. Each corrected application costs two more products K.
//
// Mixed precision: given SinglePrecisionProducts (K and M^-1 on float
// vectors), apply_single runs B on float work vectors, so that a
// mixed-precision Polonsky-Keer keeps its work vectors in float with the
// correction on: the fields (the work vector, the correction's field and
// K e_0) are floats, the block sums and the coarse solve stay double.
#pragma once

#include <Eigen/Core>

#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/solvers/block_deflation.hpp"
#include "halfspace/solvers/deflation_schedule.hpp"
#include "halfspace/solvers/preconditioner.hpp"
#include "halfspace/solvers/single_precision_products.hpp"

namespace halfspace::solvers {

class BalancingPreconditioner final : public Preconditioner {
 public:
  // Keeps references to all three, which must outlive it. Throws InputError
  // if the deflation's grid is not the operator's. `single`, if given,
  // holds K and M^-1 on float vectors (the same operators in single
  // precision) for apply_single; its precondition is required then.
  BalancingPreconditioner(InfluenceOperator& op, Preconditioner& fourier, BlockDeflation& deflation,
                          SinglePrecisionProducts single = {});

  // Outside a contact solve, or in an iteration without the correction:
  // M^-1. Otherwise B on the search set last given to adapt().
  void apply(std::span<const double> in, std::span<double> out) override;
  // The same on float vectors (needs `single`; in and out may be the same).
  void apply_single(std::span<const float> in, std::span<float> out);

  std::string_view kind() const override { return "deflated"; }
  // Forgets the schedule's verdict unless continue_next_solve() came first.
  void begin_solve() override;
  void continue_next_solve() override { continuing_ = true; }
  // Asks the schedule, and brings the coarse matrix up to the contact set
  // when the correction applies (the first time in this object's life, also
  // the kernel K e_0: one product, and the correction's field).
  bool adapt(const SearchSet& set, std::span<const double> residuals) override;
  void observe_step(const StepReport& step) override;
  // The correction's products and coarse work in this solve, and its record.
  void report(SolveResult& result) const override;

 private:
  // B in on the search set, into out (which may be in), on fields of T
  // (double, or float with `single`).
  template <class T>
  void apply_balancing(std::span<const T> in, std::span<T> out);
  // The correction's field in T, made if needed; the field of the other
  // precision is released (an active-set phase applies B in double before
  // a mixed-precision Polonsky-Keer applies it in float).
  template <class T>
  T* field();

  InfluenceOperator& op_;
  Preconditioner& fourier_;
  BlockDeflation& deflation_;
  DeflationSchedule schedule_;
  SearchSet set_;
  bool active_ = false;        // the correction applies in this iteration
  bool continuing_ = false;    // the next begin_solve() keeps the schedule
  bool kernel_known_ = false;  // deflation_ has the kernel (one product, when first needed)
  SinglePrecisionProducts single_;
  // Made when the correction first applies: Z y as a field, then K of it,
  // then K of M^-1's output (8 B per cell, 4 in float, none for a solve
  // that never deflates). In float the products' scratch serves instead
  // where they have one (single_.scratch), so that nothing is made.
  Eigen::ArrayXd coarse_field_;
  Eigen::ArrayXf single_field_;
  // This solve's work.
  int operator_applications_ = 0;
  int deflated_iterations_ = 0;
  BlockDeflationStats stats_before_;
};

}  // namespace halfspace::solvers
