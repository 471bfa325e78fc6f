// K truncated to the (2r + 1)^2 cells around a node: what the sparse
// preconditioners of the films' Newton steps (film_krylov_solver.hpp,
// mixed_film_krylov.hpp) keep of the elastic coupling. Read off one product
// of the translation-invariant operator (a unit pressure on cell 0), so K is
// never formed. Private to the library.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <span>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication::detail {

class LocalInfluence {
 public:
  // `first_row`: the first of the operator's rows this process holds (0 on
  // one process); on several, every process takes the rows of the product
  // it needs from the others. Collective then.
  LocalInfluence(InfluenceOperator& op, int radius, std::size_t first_row = 0) : grid_(op.grid()), r_(radius) {
    const std::size_t n = grid_.size();
    const std::size_t local = op.local_size();
    std::vector<double> unit(local, 0.0), column(local, 0.0);
    if (first_row == 0 && local > 0) unit[0] = 1.0;
    op.apply(unit, column);
    const auto nx = static_cast<long>(grid_.nx());
    const auto ny = static_cast<long>(grid_.ny());
    // The product's rows within r of row 0 (both sides on a periodic grid).
    std::vector<double> near;
    const auto reach = static_cast<std::size_t>(std::min<long>(r_ + 1, ny));
    if (local != n) {
      const std::size_t width = grid_.nx() * sizeof(double);
      near.assign(2 * reach * grid_.nx(), 0.0);
      const auto mine = std::as_bytes(std::span<const double>(column));
      op.communicator().fetch_rows(mine, first_row, 0,
                                   std::as_writable_bytes(std::span(near).first(reach * grid_.nx())), width);
      op.communicator().fetch_rows(mine, first_row, static_cast<std::size_t>(ny) - reach,
                                   std::as_writable_bytes(std::span(near).last(reach * grid_.nx())), width);
    }
    const auto value = [&](long cx, long cy) {
      if (local == n) return column[static_cast<std::size_t>(cy * nx + cx)];
      const long row =
          cy < static_cast<long>(reach) ? cy : static_cast<long>(reach) + cy - (ny - static_cast<long>(reach));
      return near[static_cast<std::size_t>(row * nx + cx)];
    };
    k_.assign(static_cast<std::size_t>((2 * r_ + 1) * (2 * r_ + 1)), 0.0);
    for (long oy = -r_; oy <= r_; ++oy) {
      for (long ox = -r_; ox <= r_; ++ox) {
        long cx = 0, cy = 0;
        if (grid_.periodic()) {
          cx = ((ox % nx) + nx) % nx;
          cy = ((oy % ny) + ny) % ny;
        } else {
          cx = std::abs(ox);
          cy = std::abs(oy);
          if (cx >= nx || cy >= ny) continue;
        }
        k_[offset(ox, oy)] = value(cx, cy);
      }
    }
  }

  // K_00: a cell's displacement under unit pressure on itself.
  double self() const { return k_[offset(0, 0)]; }

  // Calls visit(m, K_jm) for the cells m within the neighbourhood of cell j
  // (wrapped on periodic grids, cut at a free grid's edges), rows of offsets
  // in y, then x.
  template <class Visit>
  void for_each(std::size_t j, Visit&& visit) const {
    const auto nx = static_cast<long>(grid_.nx());
    const auto ny = static_cast<long>(grid_.ny());
    const long x = static_cast<long>(j) % nx;
    const long y = static_cast<long>(j) / nx;
    for (long oy = -r_; oy <= r_; ++oy) {
      for (long ox = -r_; ox <= r_; ++ox) {
        long mx = x + ox, my = y + oy;
        if (grid_.periodic()) {
          mx = ((mx % nx) + nx) % nx;
          my = ((my % ny) + ny) % ny;
        } else if (mx < 0 || mx >= nx || my < 0 || my >= ny) {
          continue;
        }
        visit(static_cast<std::size_t>(my * nx + mx), k_[offset(ox, oy)]);
      }
    }
  }

 private:
  std::size_t offset(long ox, long oy) const { return static_cast<std::size_t>((oy + r_) * (2 * r_ + 1) + (ox + r_)); }

  const Grid& grid_;
  int r_;
  std::vector<double> k_;  // K at offsets (dx, dy) in [-r, r]^2, row-major
};

}  // namespace halfspace::lubrication::detail
