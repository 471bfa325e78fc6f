// The pressure laws of lubricant.hpp and their derivatives (for the Newton
// solver of elastic_film.hpp).
#include "halfspace/lubrication/lubricant.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

namespace {
constexpr double kDowsonHigginsonA = 5.9e8;  // Pa
constexpr double kDowsonHigginsonB = 1.34;
}  // namespace

std::string_view to_string(Piezoviscosity law) {
  switch (law) {
    case Piezoviscosity::none:
      return "none";
    case Piezoviscosity::barus:
      return "barus";
    case Piezoviscosity::roelands:
      return "roelands";
  }
  return "unknown";
}

std::string_view to_string(Compressibility law) {
  return law == Compressibility::dowson_higginson ? "dowson-higginson" : "none";
}

Piezoviscosity parse_piezoviscosity(std::string_view text) {
  if (text == "none") return Piezoviscosity::none;
  if (text == "barus") return Piezoviscosity::barus;
  if (text == "roelands") return Piezoviscosity::roelands;
  throw InputError(fmt::format("piezoviscosity '{}' is invalid: allowed are none, barus, roelands", text));
}

Compressibility parse_compressibility(std::string_view text) {
  if (text == "none") return Compressibility::none;
  if (text == "dowson-higginson") return Compressibility::dowson_higginson;
  throw InputError(fmt::format("compressibility '{}' is invalid: allowed are none, dowson-higginson", text));
}

void LubricantLaws::validate(double ambient_viscosity) const {
  if (!(std::isfinite(pressure_viscosity) && pressure_viscosity >= 0.0)) {
    throw OptionError("pressure_viscosity", format_number(pressure_viscosity) + " 1/Pa",
                      "is invalid: the pressure-viscosity coefficient must be >= 0 and finite");
  }
  if (!(std::isfinite(roelands_index) && roelands_index >= 0.0)) {
    throw OptionError("roelands_index", format_number(roelands_index), "is invalid: it must be >= 0 and finite");
  }
  if (piezoviscosity == Piezoviscosity::barus && pressure_viscosity <= 0.0) {
    throw OptionError("pressure_viscosity", "0 1/Pa",
                      "is invalid for Barus: give the pressure-viscosity coefficient alpha > 0 (1/Pa)");
  }
  if (piezoviscosity == Piezoviscosity::roelands) {
    if (roelands_index <= 0.0 && pressure_viscosity <= 0.0) {
      throw OptionError("roelands_index", "0",
                        "is invalid without a pressure-viscosity coefficient: Roelands needs its index z > 0 or "
                        "alpha > 0 (1/Pa)");
    }
    if (!(std::log(ambient_viscosity) + kRoelandsLogViscosity > 0.0)) {
      throw OptionError("viscosity", format_number(ambient_viscosity) + " Pa s",
                        "is invalid for Roelands: it must exceed eta_inf = 6.31e-5 Pa s");
    }
  }
}

double LubricantLaws::roelands_exponent(double ambient_viscosity) const {
  if (roelands_index > 0.0) return roelands_index;
  return pressure_viscosity * kRoelandsPressure / (std::log(ambient_viscosity) + kRoelandsLogViscosity);
}

double LubricantLaws::viscosity_ratio(double pressure, double ambient_viscosity) const {
  switch (piezoviscosity) {
    case Piezoviscosity::none:
      return 1.0;
    case Piezoviscosity::barus:
      return std::exp(pressure_viscosity * pressure);
    case Piezoviscosity::roelands: {
      const double z = roelands_exponent(ambient_viscosity);
      const double scale = std::log(ambient_viscosity) + kRoelandsLogViscosity;
      return std::exp(scale * (std::pow(1.0 + pressure / kRoelandsPressure, z) - 1.0));
    }
  }
  return 1.0;
}

double LubricantLaws::viscosity_log_slope(double pressure, double ambient_viscosity) const {
  switch (piezoviscosity) {
    case Piezoviscosity::none:
      return 0.0;
    case Piezoviscosity::barus:
      return pressure_viscosity;
    case Piezoviscosity::roelands: {
      const double z = roelands_exponent(ambient_viscosity);
      const double scale = std::log(ambient_viscosity) + kRoelandsLogViscosity;
      return scale * z * std::pow(1.0 + pressure / kRoelandsPressure, z - 1.0) / kRoelandsPressure;
    }
  }
  return 0.0;
}

double LubricantLaws::density_ratio(double pressure) const {
  if (compressibility == Compressibility::none) return 1.0;
  return (kDowsonHigginsonA + kDowsonHigginsonB * pressure) / (kDowsonHigginsonA + pressure);
}

double LubricantLaws::density_ratio_slope(double pressure) const {
  if (compressibility == Compressibility::none) return 0.0;
  const double d = kDowsonHigginsonA + pressure;
  return (kDowsonHigginsonB - 1.0) * kDowsonHigginsonA / (d * d);
}

}  // namespace halfspace::lubrication
