// The four line-contact tests of Table 1 of the seed paper (Quintana Castillo,
// Luersen & Profito, "A method to evaluate contact pressure distribution of
// elastic surfaces using LCP and optimization techniques"), read as 1D
// plane-strain Hertz line contacts, and their Hertz solutions.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace::paper {

// The paper's domain x in [-4e-4, 4e-4] m, nodes at both ends.
inline constexpr double kDomainHalfWidth = 4e-4;  // m
// The paper states no load; this is the default line load (N/m).
inline constexpr double kDefaultLoad = 1e5;

// One column of Table 1. Both bodies have the same E and nu.
struct PaperTest {
  int number = 0;               // 1..4
  double radius1 = 0.0;         // R1 (m)
  double radius2 = 0.0;         // R2 (m)
  double youngs_modulus = 0.0;  // E1 = E2 (Pa)
  double poissons_ratio = 0.0;  // nu1 = nu2
  std::size_t nodes = 0;        // N
};

// Tests 1-4 in order.
const std::array<PaperTest, 4>& table1();
// Test `number` (1..4); throws InputError naming the value otherwise.
const PaperTest& table1_test(long long number);

// Hertz line contact under a load per length P' (Johnson 1985, ch. 4):
// half-width b = sqrt(4 P' R / (pi E*)), peak p_H = 2 P' / (pi b).
struct HertzLine {
  double half_width = 0.0;          // b (m)
  double peak = 0.0;                // p_H (Pa)
  double pressure(double x) const;  // p_H sqrt(1 - x^2/b^2) inside, 0 outside (Pa)
};
HertzLine hertz_line(double load, double radius, double e_star);

// A test laid out on its grid: N nodes evenly spaced over the domain with
// both ends, dx = 2 * kDomainHalfWidth / (N - 1), each the centre of a
// constant-pressure cell of width dx (a free 1D grid), and the gap
// x^2 / (2R) at zero approach.
struct LineContact {
  PaperTest test;
  Grid grid;
  std::vector<double> x;       // node positions (m)
  Eigen::ArrayXd initial_gap;  // x^2 / (2R) (m)
  double radius = 0.0;         // R = R1 R2 / (R1 + R2) (m)
  double e_star = 0.0;         // from 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Pa)
  double load = 0.0;           // N/m
  HertzLine hertz;
};
// Throws InputError unless load is positive and finite.
LineContact line_contact(const PaperTest& test, double load);

// The paper's eq. (4) taken literally on the 1D grid: the 3D point-load
// (Boussinesq) displacement (1 - nu^2) / (pi E |x_i - x_j|) with E the
// composite modulus of its eq. (5), which already holds (1 - nu^2), so the
// factor is counted twice. Its diagonal is infinite; this fills it with the
// mean of 1/r over a dx x dx square around the node, 4 ln(1 + sqrt 2)/dx,
// one arbitrary choice among many. Its units are m/N, not m/Pa: applied to
// nodal pressures it gives 1/m, not a displacement. It is what the paper's
// equations say, shown in docs/paper.md, not a model halfspace otherwise uses.
Eigen::MatrixXd point_load_matrix(const LineContact& contact);

}  // namespace halfspace::paper
