// The ranges the front ends (the program and the Python package) accept for
// physical quantities (make_problem, problem.hpp, checks them). The
// solvers take any positive, finite, normal value (their tests use E* = 1
// and unit spacings); a user works in SI units, where values far outside
// these ranges are typing mistakes, and where they would overflow or
// underflow inside the solve (an E* of 1e-300 Pa makes every displacement
// infinite) and end in a NaN breakdown or an infinite force instead of a
// clear refusal. One table, so that the CLI and Python refuse alike.
#pragma once

#include <string>
#include <string_view>

namespace halfspace {

// Lengths: spacings, domain sizes, radii, wavelengths, amplitudes, adhesion
// ranges (m).
inline constexpr double kMinLength = 1e-12;
inline constexpr double kMaxLength = 1e3;
// Moduli: E1, E2 and E* (Pa); rubbers start near 1e5, diamond is 1.2e12.
inline constexpr double kMinModulus = 1e3;
inline constexpr double kMaxModulus = 1e15;
// Pressures and stresses (Pa): the mean contact pressure over the domain
// (given or as force / area) and the adhesive stress.
inline constexpr double kMinMeanPressure = 1e-9;
inline constexpr double kMaxMeanPressure = 1e13;

// `value` if it lies in [low, high]; otherwise throws InputError
// "<what> is invalid: allowed range is [low, high] <unit>", so `what` shows
// the value: "--E-star 1e-300", "spacing dx = 1e-15 m (--size 1e-6 / --grid 1000)".
double require_in_range(const std::string& what, double value, double low, double high, std::string_view unit);

}  // namespace halfspace
