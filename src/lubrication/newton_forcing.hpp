// The forcing term of an inexact Newton iteration: the relative residual
// its Krylov solve stops at (Dembo, Eisenstat & Steihaug 1982), chosen from
// how fast the Newton residual falls.
#pragma once

#include <algorithm>
#include <cmath>

namespace halfspace::lubrication::detail {

// The loosest relative tolerance of a GMRES step (far from the solution).
inline constexpr double kLargestForcing = 1e-2;

// eta_k for ||F_k|| = `norm` after ||F_{k-1}|| = `previous_norm` (<= 0 on
// the first step: `largest`) and eta_{k-1} = `previous`: Eisenstat &
// Walker's (1996) choice 2, eta_k = gamma (||F_k|| / ||F_{k-1}||)^alpha with
// gamma = 0.9, alpha = 2, loose while the residual falls slowly (the linear
// model is no better than that) and tight as it falls fast. Safeguarded:
// not below gamma eta_{k-1}^alpha where that is above 0.1 (one good step
// does not make the next solve tight), at most `largest`, and not below half
// the stopping test's `tolerance` over ||F_k|| (no solve tighter than the
// last step needs; Kelley 1995, eq. 6.20).
inline double newton_forcing(double norm, double previous_norm, double previous, double largest, double tolerance) {
  constexpr double kGamma = 0.9;
  constexpr double kAlpha = 2.0;
  if (!(previous_norm > 0.0)) return largest;
  double forcing = kGamma * std::pow(norm / previous_norm, kAlpha);
  const double kept = kGamma * std::pow(previous, kAlpha);
  if (kept > 0.1) forcing = std::max(forcing, kept);
  forcing = std::min(forcing, largest);
  return norm > 0.0 ? std::max(forcing, std::min(largest, 0.5 * tolerance / norm)) : forcing;
}

}  // namespace halfspace::lubrication::detail
