// Resampling height maps (resample.hpp): one linear map per axis, applied
// along x, then along y.
#include "halfspace/surface/resample.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"
#include "halfspace/memory_estimate.hpp"

namespace halfspace::surface {
namespace {

// New cell k's value as weights on the old cells: weights[k] = {(i, w)}.
using AxisWeights = std::vector<std::vector<std::pair<std::size_t, double>>>;

// The piecewise-linear interpolant through the old cells' centres (at i +
// 1/2 in old-cell units), its first and last pieces extended over the outer
// half cells so that a linear profile stays linear: piece i (0 <= i <= n -
// 2) joins centres i and i + 1 and covers x in [i + 1/2, i + 3/2], the first
// from -inf and the last to +inf.
std::size_t piece_at(double x, std::size_t n) {
  const double i = std::floor(x - 0.5);
  return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(n - 2)));
}

// Refinement: the interpolant at the new centres.
AxisWeights interpolation_weights(std::size_t old_n, std::size_t new_n) {
  AxisWeights weights(new_n);
  const double ratio = static_cast<double>(old_n) / static_cast<double>(new_n);
  for (std::size_t k = 0; k < new_n; ++k) {
    const double x = (static_cast<double>(k) + 0.5) * ratio;
    const std::size_t i = piece_at(x, old_n);
    const double f = x - (static_cast<double>(i) + 0.5);
    weights[k] = {{i, 1.0 - f}, {i + 1, f}};
  }
  return weights;
}

// Coarsening: the interpolant's mean over each new cell [a, b], integrated
// exactly piece by piece. On piece i with u = x - (i + 1/2) the interpolant
// is (1 - u) h_i + u h_{i+1}.
AxisWeights averaging_weights(std::size_t old_n, std::size_t new_n) {
  AxisWeights weights(new_n);
  const double ratio = static_cast<double>(old_n) / static_cast<double>(new_n);
  for (std::size_t k = 0; k < new_n; ++k) {
    const double a = static_cast<double>(k) * ratio;
    const double b = static_cast<double>(k + 1) * ratio;
    std::vector<double> w;  // on old cells first..last
    const std::size_t first = piece_at(a, old_n);
    const std::size_t last = piece_at(b, old_n);
    w.assign(last - first + 2, 0.0);
    for (std::size_t i = first; i <= last; ++i) {
      const double begin = i == first ? a : static_cast<double>(i) + 0.5;
      const double end = i == last ? b : static_cast<double>(i) + 1.5;
      if (!(end > begin)) continue;
      const double centre = static_cast<double>(i) + 0.5;
      const double half_squares = 0.5 * ((end - centre) * (end - centre) - (begin - centre) * (begin - centre));
      w[i - first] += (end - begin) - half_squares;
      w[i - first + 1] += half_squares;
    }
    for (std::size_t m = 0; m < w.size(); ++m) {
      if (w[m] != 0.0) weights[k].emplace_back(first + m, w[m] / (b - a));
    }
  }
  return weights;
}

AxisWeights axis_weights(std::size_t old_n, std::size_t new_n) {
  return new_n >= old_n ? interpolation_weights(old_n, new_n) : averaging_weights(old_n, new_n);
}

std::string count_text(std::size_t nx, std::size_t ny, int dimension) {
  return dimension == 1 ? fmt::format("{}", nx) : fmt::format("{}x{}", nx, ny);
}

}  // namespace

Resample parse_resample(std::string_view text) {
  const auto invalid = [&] {
    return InputError(fmt::format(
        "resample '{}' is invalid: expected NXxNY (cells along x and y) for a map or N for a profile", text));
  };
  const auto count = [&](std::string_view field) {
    std::size_t value = 0;
    const auto [stop, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc() || stop != field.data() + field.size()) throw invalid();
    return value;
  };
  const std::size_t cross = text.find('x');
  if (cross == std::string_view::npos) return Resample{count(text), 1, 1};
  return Resample{count(text.substr(0, cross)), count(text.substr(cross + 1)), 2};
}

void resample(HeightMap& map, const Resample& resample) {
  const std::string named = fmt::format("resample {}", count_text(resample.nx, resample.ny, resample.dimension));
  const std::string shape =
      map.dimension == 1 ? fmt::format("{}-point profile", map.nx) : fmt::format("{}x{} map (nx x ny)", map.nx, map.ny);
  if (resample.dimension != map.dimension) {
    throw InputError(fmt::format("{} is invalid for the {} of {}: give {}", named, shape, map.source,
                                 map.dimension == 1 ? "N" : "NXxNY"));
  }
  if (!map.all_valid()) {
    throw InputError(
        fmt::format("{}: the {} of {} has invalid points; fill or crop them first", named, shape, map.source));
  }
  if (!(map.dx > 0.0) || (map.dimension == 2 && !(map.dy > 0.0))) {
    throw InputError(fmt::format("{}: the {} of {} has no spacing to keep its lengths", named, shape, map.source));
  }
  const auto check_axis = [&](std::string_view axis, std::size_t old_n, std::size_t new_n) {
    if (new_n < 2) throw InputError(fmt::format("{} is invalid: need at least 2 cells along {}", named, axis));
    if (old_n < 2) {
      throw InputError(fmt::format("{}: the {} of {} has a single point along {}; nothing to interpolate", named, shape,
                                   map.source, axis));
    }
    if (new_n / kMaxResampleRefinement > old_n ||
        (new_n / kMaxResampleRefinement == old_n && new_n % kMaxResampleRefinement != 0)) {
      throw InputError(
          fmt::format("{} is invalid: {} cells along {} refine the {} of {} more than {} times (at most "
                      "{} cells)",
                      named, new_n, axis, shape, map.source, kMaxResampleRefinement, old_n * kMaxResampleRefinement));
    }
  };
  check_axis("x", map.nx, resample.nx);
  if (map.dimension == 2) check_axis("y", map.ny, resample.ny);
  const std::size_t new_ny = map.dimension == 1 ? 1 : resample.ny;
  if (resample.nx == map.nx && new_ny == map.ny) return;
  // The new map and the half-way one (new columns, old rows).
  const auto cells = checked_multiply(resample.nx, std::max(new_ny, map.ny));
  if (!cells || *cells > kMaxGridCells) {
    throw InputError(fmt::format("{} is invalid: the map would have too many cells", named));
  }
  const double needed = 16.0 * static_cast<double>(*cells);
  if (const auto available = available_memory(); available && needed > available->bytes) {
    throw InputError(fmt::format("{}: the resampled map needs about {}, more than the {} available ({})", named,
                                 format_bytes(needed), format_bytes(available->bytes), available->source));
  }

  const std::size_t old_nx = map.nx, old_ny = map.ny;
  const AxisWeights along_x = axis_weights(old_nx, resample.nx);
  Eigen::ArrayXd rows_done(static_cast<Eigen::Index>(resample.nx * old_ny));
  for (std::size_t j = 0; j < old_ny; ++j) {
    for (std::size_t k = 0; k < resample.nx; ++k) {
      double sum = 0.0;
      for (const auto& [i, w] : along_x[k]) sum += w * map.heights[static_cast<Eigen::Index>(j * old_nx + i)];
      rows_done[static_cast<Eigen::Index>(j * resample.nx + k)] = sum;
    }
  }
  Eigen::ArrayXd heights;
  if (new_ny == old_ny) {
    heights = std::move(rows_done);
  } else {
    heights.setZero(static_cast<Eigen::Index>(resample.nx * new_ny));
    const AxisWeights along_y = axis_weights(old_ny, new_ny);
    const auto nx = static_cast<Eigen::Index>(resample.nx);
    for (std::size_t k = 0; k < new_ny; ++k) {
      for (const auto& [j, w] : along_y[k]) {
        heights.segment(static_cast<Eigen::Index>(k) * nx, nx) +=
            w * rows_done.segment(static_cast<Eigen::Index>(j) * nx, nx);
      }
    }
  }
  const double old_dx = map.dx, old_dy = map.dy;
  map.dx = old_dx * static_cast<double>(old_nx) / static_cast<double>(resample.nx);
  if (map.dimension == 2) map.dy = old_dy * static_cast<double>(old_ny) / static_cast<double>(new_ny);
  map.heights = std::move(heights);
  map.nx = resample.nx;
  map.ny = new_ny;
  const auto method = [](std::size_t from, std::size_t to) {
    return to > from ? "linear interpolation" : to < from ? "cell means" : "unchanged";
  };
  map.preparation.push_back(
      map.dimension == 1
          ? fmt::format("resample: {} points to {} over the same length (dx {:.6g} m to {:.6g} m; {})", old_nx, map.nx,
                        old_dx, map.dx, method(old_nx, map.nx))
          : fmt::format("resample: the {}x{} map to {}x{} over the same lengths (dx {:.6g} m to {:.6g} m, dy {:.6g} m "
                        "to {:.6g} m; x: {}, y: {})",
                        old_nx, old_ny, map.nx, map.ny, old_dx, map.dx, old_dy, map.dy, method(old_nx, map.nx),
                        method(old_ny, map.ny)));
}

}  // namespace halfspace::surface
