// A preconditioner for contact solvers: an approximation of the inverse of
// the influence operator, z = M^-1 r, applied to residuals (gaps). Within a
// contact solve M^-1 may depend on the iterate's active set, which the
// solver reports before each application (adapt) and after each step
// (observe_step); a plain M^-1, such as the Fourier one, ignores both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

#include "halfspace/solvers/solve_result.hpp"

namespace halfspace::solvers {

// The cells a contact solver's search direction covers, read from its
// current iterate: the contact set {p > 0}, and with `overlap` also the
// cells out of contact that interpenetrate {p = 0, g < 0} (see
// polonsky_keer.hpp). With a hardness cap (`upper` finite) a cell at the cap
// leaves the set while its gap is not positive (it stays plastic) and is in
// it while the gap says its pressure should fall, the mirror of the cells
// out of contact. Under `mean_free` (load control) directions must be
// mean-free on the set, so that a step keeps the force.
//
// The gap g = g0 + u - approach is computed where read, from the initial
// gap g0, the displacement u and the approach (which the solver updates in
// place), as Polonsky-Keer computes it: the solver stores no gap field.
struct SearchSet {
  const double* pressure = nullptr;
  const double* initial_gap = nullptr;
  const double* displacement = nullptr;
  const double* approach = nullptr;
  bool overlap = false;
  bool mean_free = false;
  double upper = std::numeric_limits<double>::infinity();  // the cap (Pa)
  // Instead of the fields above: the set {mask != 0} of a byte mask (the
  // active-set phase's fixed set, active_set_start.hpp), every cell of it
  // in contact below the cap.
  const std::uint8_t* mask = nullptr;
  // With the fields: the set as it is now, a byte per cell, which
  // contains(i) reads instead of p, g0 and u (a solver's snapshot, valid
  // until it moves p or u).
  const std::uint8_t* search_mask = nullptr;

  static SearchSet of_mask(const std::uint8_t* mask, bool mean_free) {
    SearchSet set;
    set.mean_free = mean_free;
    set.mask = mask;
    return set;
  }

  double gap(std::size_t i) const { return initial_gap[i] + displacement[i] - *approach; }
  // In contact and below the cap: the cells whose gap vanishes at the
  // solution (the elastic part of the contact).
  bool in_contact(std::size_t i) const { return mask ? mask[i] != 0 : (pressure[i] > 0.0) & (pressure[i] < upper); }
  bool contains(std::size_t i) const {
    if (mask) return mask[i] != 0;
    return search_mask ? search_mask[i] != 0 : contains(i, gap(i));
  }
  // The same for a set of the fields (no mask) and a cell whose gap g the
  // caller has at hand. Bitwise, not short-circuit, so that masks over the
  // cells stay free of branches (contact edges are everywhere).
  bool contains(std::size_t i, double g) const {
    return ((pressure[i] > 0.0) | (overlap & (g < 0.0))) & ((pressure[i] < upper) | (g > 0.0));
  }
};

// What a step of a contact solve did, for preconditioners that adapt.
struct StepReport {
  double clipped = 0.0;   // cells whose pressure the bounds or entries changed
  double searched = 0.0;  // cells in the search set
};

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // out = M^-1 in, both with one entry per cell; `out` may be `in` itself
  // (in place). M^-1 must be symmetric positive definite (on the mean-free
  // fields of the search set, for an adapting one). Allocates nothing.
  virtual void apply(std::span<const double> in, std::span<double> out) = 0;

  // How a solver built on it names itself: "<kind>-polonsky-keer".
  virtual std::string_view kind() const { return "preconditioned"; }
  // A contact solve begins.
  virtual void begin_solve() {}
  // The next begin_solve() continues the iteration of the current solve on
  // the same contact (a phase handing over to the solver that finishes):
  // an adapting M^-1 keeps what it has learned about the iteration.
  virtual void continue_next_solve() {}
  // Before an application in a contact solve: the iterate's search set
  // (valid until the application; a byte mask in it, mask or search_mask,
  // spares the application's passes three fields per cell) and the
  // residuals so far. Returns whether
  // M^-1 changed since the last application, so that the solver restarts
  // its conjugate directions.
  virtual bool adapt(const SearchSet& /*set*/, std::span<const double> /*residuals*/) { return false; }
  // After each step of a contact solve.
  virtual void observe_step(const StepReport& /*step*/) {}
  // A contact solve ends: adds the work M^-1 did beyond its applications
  // (which the solver counts) to `result`.
  virtual void report(SolveResult& /*result*/) const {}
};

}  // namespace halfspace::solvers
