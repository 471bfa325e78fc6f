// Table 1 of the seed paper as data, its line-contact reading, the Hertz line
// contact, and the paper's eq. (4) kernel for showing what it gives.
#include "halfspace/paper/table1.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "halfspace/error.hpp"
#include "halfspace/material.hpp"

namespace halfspace::paper {

const std::array<PaperTest, 4>& table1() {
  static const std::array<PaperTest, 4> tests{{
      {1, 0.05, 0.03, 210e9, 0.3, 129},
      {2, 0.01, 0.01, 82.7e9, 0.345, 500},
      {3, 0.5, 0.0005, 115.7e9, 0.321, 500},
      {4, 0.05, 0.03, 78e9, 0.293, 7},
  }};
  return tests;
}

const PaperTest& table1_test(long long number) {
  if (number < 1 || number > 4) {
    throw InputError(fmt::format("test = {} is invalid: Table 1 has tests 1 to 4", number));
  }
  return table1()[static_cast<std::size_t>(number - 1)];
}

double HertzLine::pressure(double x) const {
  const double s = 1.0 - (x * x) / (half_width * half_width);
  return s > 0.0 ? peak * std::sqrt(s) : 0.0;
}

HertzLine hertz_line(double load, double radius, double e_star) {
  const double b = std::sqrt(4.0 * load * radius / (std::numbers::pi * e_star));
  return {b, 2.0 * load / (std::numbers::pi * b)};
}

LineContact line_contact(const PaperTest& test, double load) {
  if (!(std::isfinite(load) && load > 0.0)) {
    throw InputError(fmt::format("load = {} N/m is invalid: must be positive and finite", format_number(load)));
  }
  const double dx = 2.0 * kDomainHalfWidth / static_cast<double>(test.nodes - 1);
  const ElasticBody body{test.youngs_modulus, test.poissons_ratio};
  LineContact contact{test,
                      Grid::line(test.nodes, dx, Boundary::free),
                      std::vector<double>(test.nodes),
                      Eigen::ArrayXd(static_cast<Eigen::Index>(test.nodes)),
                      test.radius1 * test.radius2 / (test.radius1 + test.radius2),
                      composite_modulus(body, body),
                      load,
                      {}};
  for (std::size_t i = 0; i < test.nodes; ++i) {
    // Measured from the left end, so that both ends are exact.
    const double x = -kDomainHalfWidth + static_cast<double>(i) * dx;
    contact.x[i] = x;
    contact.initial_gap[static_cast<Eigen::Index>(i)] = x * x / (2.0 * contact.radius);
  }
  contact.hertz = hertz_line(load, contact.radius, contact.e_star);
  return contact;
}

Eigen::MatrixXd point_load_matrix(const LineContact& contact) {
  const double nu = contact.test.poissons_ratio;
  const double factor = (1.0 - nu * nu) / (std::numbers::pi * contact.e_star);
  const double dx = contact.grid.dx();
  const auto n = static_cast<Eigen::Index>(contact.x.size());
  Eigen::MatrixXd matrix(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const double r = std::abs(contact.x[static_cast<std::size_t>(i)] - contact.x[static_cast<std::size_t>(j)]);
      matrix(i, j) = i == j ? factor * 4.0 * std::log1p(std::numbers::sqrt2) / dx : factor / r;
    }
  }
  return matrix;
}

}  // namespace halfspace::paper
