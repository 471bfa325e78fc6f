// Helpers shared by the operator tests: reproducible random fields and the
// relative max-norm error with the cell where it occurs.
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace halfspace::testing {

// Uniform values in [0, 1): non-negative, like contact pressures.
inline std::vector<double> random_field(std::size_t n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> values(n);
  for (double& v : values) v = uniform(engine);
  return values;
}

struct MaxError {
  double relative = 0.0;  // max |actual - expected| / max |expected|
  std::size_t index = 0;  // cell of the largest |actual - expected|
};

inline MaxError max_error(const std::vector<double>& actual, const std::vector<double>& expected) {
  double scale = 0.0;
  MaxError result;
  double worst = -1.0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    scale = std::max(scale, std::abs(expected[i]));
    const double difference = std::abs(actual[i] - expected[i]);
    if (difference > worst) {
      worst = difference;
      result.index = i;
    }
  }
  result.relative = worst / scale;
  return result;
}

}  // namespace halfspace::testing
