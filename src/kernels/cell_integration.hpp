// Integration over one rectangular cell: the corner primitive shared by the
// closed forms, and tensor Gauss-Legendre rules, for the point-load
// kernels of the free influence coefficients (Love's normal, Cerruti's
// tangential) away from the cell, where their closed forms cancel: their
// corner terms are O(R ln R) or O(R) while the result is O(ab/R), so the
// relative error grows like 7 (R/h)^2 eps at distance R in units of the
// half-diagonal h = sqrt(a^2 + b^2). Beyond 2h the tensor rule is accurate to
// below 1e-17 relative for 1/r (checked against 40-digit evaluations of
// Love's closed form in all directions, aspect ratios 1/100 to 100) with 16
// points per axis from 2h, 8 from 6h and 4 from 64h; Cerruti's kernels
// x^2/r^3, y^2/r^3, xy/r^3 are as smooth on the cell and use the same
// distances (tests/kernels/cerruti_rectangle_test.cpp).
// Internal to src/kernels.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace halfspace::kernels {

// s * asinh(t / |s|), written so that it is exact at s = 0 (its limit, 0) and
// never divides by a tiny |s|: for |t| > |s| the logarithm form is used, whose
// difference ln(|t| + r) - ln|s| > ln(1 + sqrt 2) cannot cancel. Its mixed
// derivative is t^2/r^3 (r = sqrt(s^2 + t^2)); with its mirror it is the
// primitive of 1/r.
inline double signed_asinh_term(double s, double t) {
  if (s == 0.0 || t == 0.0) return 0.0;
  const double as = std::abs(s);
  const double at = std::abs(t);
  const double magnitude = at <= as ? std::asinh(at / as) : std::log(at + std::hypot(s, t)) - std::log(as);
  return std::copysign(1.0, t) * s * magnitude;
}

// The positive half of the symmetric nodes on [-1, 1] and their weights
// (values from Newton iteration on P_n in 40-digit arithmetic).
struct CellGaussRule {
  std::array<double, 8> nodes;
  std::array<double, 8> weights;
  std::size_t count;
};
inline constexpr CellGaussRule kCellGauss4{
    {0.861136311594052575224, 0.339981043584856264803}, {0.347854845137453857373, 0.652145154862546142627}, 2};
inline constexpr CellGaussRule kCellGauss8{
    {0.960289856497536231684, 0.796666477413626739592, 0.525532409916328985818, 0.183434642495649804939},
    {0.101228536290376259153, 0.222381034453374470544, 0.313706645877887287338, 0.362683783378361982965},
    4};
inline constexpr CellGaussRule kCellGauss16{
    {0.989400934991649932596, 0.944575023073232576078, 0.86563120238783174388, 0.755404408355003033895,
     0.617876244402643748447, 0.458016777657227386342, 0.28160355077925891323, 0.0950125098376374401853},
    {0.0271524594117540948518, 0.0622535239386478928628, 0.0951585116824927848099, 0.124628971255533872052,
     0.149595988816576732082, 0.169156519395002538189, 0.182603415044923588867, 0.189450610455068496285},
    8};

inline constexpr double kCellGauss16Distance = 2.0;
inline constexpr double kCellGauss8Distance = 6.0;
inline constexpr double kCellGauss4Distance = 64.0;

// The rule for the offset (x, y) from a cell of half-widths (a, b), or null
// within 2h, where the closed form is used (it loses < ~30 eps there).
inline const CellGaussRule* far_field_rule(double x, double y, double a, double b) {
  const double r2 = x * x + y * y;
  const double h2 = a * a + b * b;
  if (r2 >= kCellGauss4Distance * kCellGauss4Distance * h2) return &kCellGauss4;
  if (r2 >= kCellGauss8Distance * kCellGauss8Distance * h2) return &kCellGauss8;
  if (r2 >= kCellGauss16Distance * kCellGauss16Distance * h2) return &kCellGauss16;
  return nullptr;
}

// Integral of kernel(x - x', y - y') over |x'| <= a, |y'| <= b by the rule:
// each node (i, j) with its four mirror images.
template <class Kernel>
double cell_gauss_integral(double x, double y, double a, double b, const CellGaussRule& rule, Kernel&& kernel) {
  double total = 0.0;
  for (std::size_t i = 0; i < rule.count; ++i) {
    const double sx = a * rule.nodes[i];
    double row = 0.0;
    for (std::size_t j = 0; j < rule.count; ++j) {
      const double sy = b * rule.nodes[j];
      const double sum =
          kernel(x - sx, y - sy) + kernel(x + sx, y - sy) + kernel(x - sx, y + sy) + kernel(x + sx, y + sy);
      row += rule.weights[j] * sum;
    }
    total += rule.weights[i] * row;
  }
  return a * b * total;
}

}  // namespace halfspace::kernels
