// Gauss-Legendre rules for the tests that integrate point-force solutions
// numerically over a cell (the independent check of closed forms).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace halfspace::testing {

struct QuadratureRule {
  std::vector<double> nodes;  // on [-1, 1]
  std::vector<double> weights;
};

// The n-point rule, its nodes by Newton's iteration on P_n.
inline QuadratureRule gauss_legendre(int n) {
  QuadratureRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(x);
    rule.weights.push_back(2.0 / ((1.0 - x * x) * derivative * derivative));
  }
  return rule;
}

}  // namespace halfspace::testing
