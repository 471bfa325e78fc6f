#include "dry_contact_memo.hpp"

#include <algorithm>
#include <span>

#include "halfspace/solvers/polonsky_keer.hpp"

namespace halfspace::lubrication::detail {

const solvers::SolveResult& DryContactMemo::solve(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                                  const solvers::Loading& loading) {
  const Grid& grid = op.grid();
  const std::size_t ny = grid.dimension() == 2 ? grid.ny() : 1;
  const auto same_grid = [&](const Kept& kept) { return kept.op == &op && kept.nx == grid.nx() && kept.ny == ny; };
  auto slot = std::find_if(kept_.begin(), kept_.end(), same_grid);
  // The gap's values, not its address: a coarser grid's operator and gap
  // are made anew for each grid sequence and may reuse a freed address.
  const bool here = slot != kept_.end() && slot->loading.mode == loading.mode && slot->loading.value == loading.value &&
                    slot->gap.size() == gap.size() && std::equal(gap.begin(), gap.end(), slot->gap.begin());
  // Every process solves, or none does (the solve is collective).
  if (op.communicator().min(here ? 1.0 : 0.0) > 0.5) return slot->result;
  if (slot == kept_.end()) {
    slot = kept_.emplace(kept_.end());
    slot->op = &op;
    slot->nx = grid.nx();
    slot->ny = ny;
  }
  solvers::PolonskyKeer solver(op);
  slot->result = solver.solve({gap.data(), static_cast<std::size_t>(gap.size())}, loading);
  slot->gap = gap;
  slot->loading = loading;
  ++solves_;
  return slot->result;
}

}  // namespace halfspace::lubrication::detail
