// How a lubricant's viscosity and density grow with pressure: the laws an
// elastohydrodynamic film needs, where the pressure reaches GPa.
//
//   Barus (1893):     eta = eta0 exp(alpha p)
//   Roelands (1966):  eta = eta0 exp( (ln eta0 + 9.67) ((1 + p / p0)^z - 1) ),
//                     p0 = 1.96e8 Pa, eta in Pa s
//   Dowson & Higginson (1966):  rho / rho0 = (5.9e8 + 1.34 p) / (5.9e8 + p), p in Pa
//
// Roelands' index z is given, or follows from a pressure-viscosity
// coefficient alpha as z = alpha p0 / (ln eta0 + 9.67), the z whose slope
// d ln eta / dp at p = 0 is alpha.
#pragma once

#include <string_view>

namespace halfspace::lubrication {

enum class Piezoviscosity { none, barus, roelands };
enum class Compressibility { none, dowson_higginson };

std::string_view to_string(Piezoviscosity law);
std::string_view to_string(Compressibility law);
// Parse "none", "barus", "roelands" / "none", "dowson-higginson"; throw
// InputError naming the value and the allowed ones otherwise.
Piezoviscosity parse_piezoviscosity(std::string_view text);
Compressibility parse_compressibility(std::string_view text);

inline constexpr double kRoelandsPressure = 1.96e8;    // Pa, p0
inline constexpr double kRoelandsLogViscosity = 9.67;  // -ln(eta_inf / (1 Pa s)), eta_inf = 6.31e-5 Pa s

struct LubricantLaws {
  Piezoviscosity piezoviscosity = Piezoviscosity::none;
  double pressure_viscosity = 0.0;  // alpha (1/Pa): Barus' coefficient; Roelands' z from it when roelands_index is 0
  double roelands_index = 0.0;      // z (Roelands only); 0 derives it from alpha
  Compressibility compressibility = Compressibility::none;

  // Throws OptionError naming the option unless alpha >= 0 and finite (> 0
  // for Barus), z >= 0 and finite, Roelands has z > 0 or alpha > 0, and
  // Roelands' ambient viscosity is above eta_inf = 6.31e-5 Pa s.
  void validate(double ambient_viscosity) const;

  // Roelands' z in force (the given one or the one from alpha).
  double roelands_exponent(double ambient_viscosity) const;

  // eta(p) / eta0 and d ln eta / dp (1/Pa), for p >= 0.
  double viscosity_ratio(double pressure, double ambient_viscosity) const;
  double viscosity_log_slope(double pressure, double ambient_viscosity) const;
  // rho(p) / rho0 and its derivative (1/Pa), for p >= 0.
  double density_ratio(double pressure) const;
  double density_ratio_slope(double pressure) const;
};

}  // namespace halfspace::lubrication
