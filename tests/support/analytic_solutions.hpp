// Closed-form contact solutions used as references by the validation tests
// (Johnson, Contact Mechanics, 1985; Westergaard 1939; Johnson, Greenwood &
// Higginson 1985). SI units.
#pragma once

#include <cmath>
#include <numbers>

namespace halfspace::testing {

// Hertz line contact under load per length `load` (N/m).
struct HertzLine {
  double half_width;  // b = sqrt(4 P' R / (pi E*))
  double peak;        // p0 = 2 P' / (pi b)
  double pressure(double x) const {
    const double s = 1.0 - (x * x) / (half_width * half_width);
    return s > 0.0 ? peak * std::sqrt(s) : 0.0;
  }
};

inline HertzLine hertz_line(double load, double radius, double e_star) {
  const double b = std::sqrt(4.0 * load * radius / (std::numbers::pi * e_star));
  return {b, 2.0 * load / (std::numbers::pi * b)};
}

// Hertz point contact under force `force` (N).
struct HertzPoint {
  double radius;    // a = (3 F R / (4 E*))^(1/3)
  double peak;      // p0 = 3 F / (2 pi a^2)
  double approach;  // a^2 / R
  double pressure(double r) const {
    const double s = 1.0 - (r * r) / (radius * radius);
    return s > 0.0 ? peak * std::sqrt(s) : 0.0;
  }
};

inline HertzPoint hertz_point(double force, double sphere_radius, double e_star) {
  const double a = std::cbrt(3.0 * force * sphere_radius / (4.0 * e_star));
  return {a, 3.0 * force / (2.0 * std::numbers::pi * a * a), a * a / sphere_radius};
}

// Hamrock & Dowson's (1977) fit of the central and minimum film of a
// circular (k = 1) EHL point contact, H = h / R, in the speed, material and
// load parameters U = eta0 u / (E' R), G = alpha E', W = F / (E' R^2).
struct HamrockDowsonFilm {
  double central, minimum;
};

inline HamrockDowsonFilm hamrock_dowson_point(double u, double g, double w) {
  return {2.69 * std::pow(u, 0.67) * std::pow(g, 0.53) * std::pow(w, -0.067) * (1.0 - 0.61 * std::exp(-0.73)),
          3.63 * std::pow(u, 0.68) * std::pow(g, 0.49) * std::pow(w, -0.073) * (1.0 - std::exp(-0.68))};
}

// Westergaard's periodic wave g0 = amplitude (1 - cos(2 pi x / wavelength)).
struct Westergaard {
  double wavelength;
  double amplitude;
  double e_star;

  // Mean pressure for full contact, p* = pi E* amplitude / wavelength.
  double full_contact_pressure() const { return std::numbers::pi * e_star * amplitude / wavelength; }
  // Contact half-width a under mean pressure p: p = p* sin^2(pi a / lambda).
  double half_width(double mean_pressure) const {
    return wavelength / std::numbers::pi * std::asin(std::sqrt(mean_pressure / full_contact_pressure()));
  }
  double pressure(double x, double mean_pressure) const {
    const double a = half_width(mean_pressure);
    const double sa2 = std::pow(std::sin(std::numbers::pi * a / wavelength), 2);
    const double sx2 = std::pow(std::sin(std::numbers::pi * x / wavelength), 2);
    if (sx2 >= sa2) return 0.0;
    return 2.0 * mean_pressure * std::cos(std::numbers::pi * x / wavelength) / sa2 * std::sqrt(sa2 - sx2);
  }
};

}  // namespace halfspace::testing
