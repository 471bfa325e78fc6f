// K truncated to the (2r + 1)^2 cells around a node: what the sparse
// preconditioners of the films' Newton steps (film_krylov_solver.hpp,
// mixed_film_krylov.hpp) keep of the elastic coupling. Read off one product
// of the translation-invariant operator (a unit pressure on cell 0), so K is
// never formed. Private to the library.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/operators/influence_operator.hpp"

namespace halfspace::lubrication::detail {

class LocalInfluence {
 public:
  LocalInfluence(InfluenceOperator& op, int radius) : grid_(op.grid()), r_(radius) {
    const std::size_t n = grid_.size();
    std::vector<double> unit(n, 0.0), column(n, 0.0);
    unit[0] = 1.0;
    op.apply(unit, column);
    const auto nx = static_cast<long>(grid_.nx());
    const auto ny = static_cast<long>(grid_.ny());
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
        k_[offset(ox, oy)] = column[static_cast<std::size_t>(cy * nx + cx)];
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
