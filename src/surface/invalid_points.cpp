// Invalid points: the refusal message, harmonic filling (a sparse SPD system
// in the invalid points only) and the largest valid rectangle (the classic
// histogram-and-stack maximal rectangle, O(nx ny)).
#include "halfspace/surface/invalid_points.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/surface/window.hpp"

namespace halfspace::surface {
namespace {

std::string where(const HeightMap& map, std::size_t k) {
  return map.dimension == 1 ? fmt::format("i = {}", k)
                            : fmt::format("(j, i) = ({}, {}) (row j, column i)", k / map.nx, k % map.nx);
}

// Cuts off the edge rows and columns without a valid point; returns false
// when there is no valid point at all.
bool trim_invalid_border(HeightMap& map, std::string& record) {
  std::size_t i_min = map.nx, i_max = 0, j_min = map.ny, j_max = 0;
  for (std::size_t j = 0; j < map.ny; ++j) {
    for (std::size_t i = 0; i < map.nx; ++i) {
      if (!map.is_valid(j * map.nx + i)) continue;
      i_min = std::min(i_min, i);
      i_max = std::max(i_max, i);
      j_min = std::min(j_min, j);
      j_max = std::max(j_max, j);
    }
  }
  if (i_min > i_max) return false;
  if (i_min == 0 && j_min == 0 && i_max == map.nx - 1 && j_max == map.ny - 1) return true;
  record = map.dimension == 1
               ? fmt::format(" after cutting the invalid ends, keeping points {} to {} of {}", i_min, i_max, map.nx)
               : fmt::format(
                     " after cutting the fully invalid border, keeping columns {} to {} and rows {} to {} of "
                     "the {}x{} map",
                     i_min, i_max, j_min, j_max, map.nx, map.ny);
  extract_window(map, i_min, j_min, i_max - i_min + 1, j_max - j_min + 1);
  return true;
}

}  // namespace

std::string_view to_string(InvalidPoints policy) {
  switch (policy) {
    case InvalidPoints::refuse:
      return "refuse";
    case InvalidPoints::fill:
      return "fill";
    case InvalidPoints::crop:
      return "crop";
  }
  return "unknown";
}

InvalidPoints parse_invalid_points(std::string_view text) {
  if (text == "refuse") return InvalidPoints::refuse;
  if (text == "fill") return InvalidPoints::fill;
  if (text == "crop") return InvalidPoints::crop;
  throw InputError(fmt::format("invalid-point handling '{}' is unknown: use refuse, fill or crop", text));
}

std::size_t count_invalid(const HeightMap& map) {
  return static_cast<std::size_t>(std::count(map.valid.begin(), map.valid.end(), std::uint8_t{0}));
}

void refuse_invalid_points(const HeightMap& map) {
  refuse_invalid_points_rows(map, 0, linalg::serial_communicator());
}

void refuse_invalid_points_rows(const HeightMap& map, std::size_t first_row, const linalg::Communicator& comm) {
  // Counts and indices as doubles: exact below 2^53 cells.
  double count = static_cast<double>(count_invalid(map));
  const auto local_first = std::find(map.valid.begin(), map.valid.end(), std::uint8_t{0});
  double first =
      local_first == map.valid.end()
          ? std::numeric_limits<double>::infinity()
          : static_cast<double>(first_row * map.nx + static_cast<std::size_t>(local_first - map.valid.begin()));
  if (comm.size() > 1) {
    comm.sum({&count, 1});
    first = comm.min(first);
  }
  if (count == 0.0) return;
  throw FileError(fmt::format(
      "height map {}: {} of {} heights are invalid (not finite, or marked invalid by the "
      "file); the first is at {}; fill them or crop to the valid region",
      map.source, static_cast<std::size_t>(count), map.size(), where(map, static_cast<std::size_t>(first))));
}

void fill_invalid_points(HeightMap& map) {
  if (count_invalid(map) == 0) {
    map.valid.clear();
    return;
  }
  std::string trimmed;
  if (!trim_invalid_border(map, trimmed)) {
    throw InputError(fmt::format("height map {}: no point is valid; there is nothing to fill from", map.source));
  }
  if (map.nx < 2 || (map.dimension == 2 && map.ny < 2)) {
    throw InputError(fmt::format("height map {}: the valid points span {} x {} points; need at least 2 along each axis",
                                 map.source, map.nx, map.ny));
  }

  if (count_invalid(map) == 0) {
    map.valid.clear();
    map.preparation.push_back(fmt::format("invalid points: none left to fill{}", trimmed));
    return;
  }
  // Unknowns: the invalid points, numbered in storage order.
  const std::size_t n = map.size();
  std::vector<Eigen::Index> unknown(n, -1);
  Eigen::Index count = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!map.is_valid(k)) unknown[k] = count++;
  }
  const double wx = map.dx > 0.0 ? 1.0 / (map.dx * map.dx) : 1.0;
  const double wy = map.dy > 0.0 ? 1.0 / (map.dy * map.dy) : 1.0;
  // Row scaling by 1/(wx + wy) keeps the entries O(1) whatever the spacing.
  const double scale = 1.0 / (wx + (map.dimension == 2 ? wy : 0.0));

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(count) * 5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(count);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Index row = unknown[k];
    if (row < 0) continue;
    const std::size_t i = k % map.nx;
    const std::size_t j = k / map.nx;
    double diagonal = 0.0;
    const auto couple = [&](std::size_t neighbour, double weight) {
      diagonal += weight * scale;
      if (unknown[neighbour] >= 0) {
        entries.emplace_back(row, unknown[neighbour], -weight * scale);
      } else {
        rhs[row] += weight * scale * map.heights[static_cast<Eigen::Index>(neighbour)];
      }
    };
    // Zero flux across the edges: a missing neighbour contributes nothing.
    if (i > 0) couple(k - 1, wx);
    if (i + 1 < map.nx) couple(k + 1, wx);
    if (j > 0) couple(k - map.nx, wy);
    if (j + 1 < map.ny) couple(k + map.nx, wy);
    entries.emplace_back(row, row, diagonal);
  }
  Eigen::SparseMatrix<double> laplacian(count, count);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  // Every connected group of invalid points touches a valid one (the map has
  // one), so the matrix is symmetric positive definite.
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  const Eigen::VectorXd filled = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !filled.allFinite()) {
    throw InputError(fmt::format("height map {}: the harmonic fill of {} points failed", map.source, count));
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (unknown[k] >= 0) map.heights[static_cast<Eigen::Index>(k)] = filled[unknown[k]];
  }
  map.valid.clear();
  map.preparation.push_back(
      fmt::format("invalid points: filled {} of {} points by harmonic (Laplace) interpolation "
                  "of the valid points{}",
                  count, n, trimmed.empty() ? std::string() : ";" + trimmed));
}

void crop_to_valid_points(HeightMap& map) {
  if (count_invalid(map) == 0) {
    map.valid.clear();
    return;
  }
  // For each row j, run[i] = valid points in column i ending at row j; the
  // largest rectangle with its bottom on row j is the largest rectangle under
  // that histogram, found with a stack of increasing bars.
  std::vector<std::size_t> run(map.nx, 0);
  std::vector<std::size_t> stack;
  // Best so far: more points, then the top-most, then the left-most.
  std::size_t best_area = 0, best_i0 = 0, best_j0 = 0, best_nx = 0, best_ny = 0;
  const auto consider = [&](std::size_t i0, std::size_t j0, std::size_t nx, std::size_t ny) {
    const std::size_t area = nx * ny;
    const bool better = area > best_area || (area == best_area && (j0 < best_j0 || (j0 == best_j0 && i0 < best_i0)));
    if (!better) return;
    best_area = area;
    best_i0 = i0;
    best_j0 = j0;
    best_nx = nx;
    best_ny = ny;
  };
  for (std::size_t j = 0; j < map.ny; ++j) {
    for (std::size_t i = 0; i < map.nx; ++i) run[i] = map.is_valid(j * map.nx + i) ? run[i] + 1 : 0;
    stack.clear();
    for (std::size_t i = 0; i <= map.nx; ++i) {
      const std::size_t height = i < map.nx ? run[i] : 0;
      while (!stack.empty() && run[stack.back()] >= height) {
        const std::size_t bar = run[stack.back()];
        stack.pop_back();
        const std::size_t left = stack.empty() ? 0 : stack.back() + 1;
        if (bar > 0) consider(left, j + 1 - bar, i - left, bar);
      }
      stack.push_back(i);
    }
  }
  if (best_nx < 2 || (map.dimension == 2 && best_ny < 2)) {
    throw InputError(
        fmt::format("height map {}: the largest rectangle of valid points is {} x {} points; need at least "
                    "2 along each axis (fill the invalid points instead)",
                    map.source, best_nx, best_ny));
  }
  const std::size_t old_nx = map.nx;
  const std::size_t old_ny = map.ny;
  const std::size_t invalid = count_invalid(map);
  extract_window(map, best_i0, best_j0, best_nx, best_ny);
  map.preparation.push_back(
      map.dimension == 1
          ? fmt::format("invalid points: cropped to the longest run of valid points, points {} to {} of {} ({} invalid "
                        "points in the profile)",
                        best_i0, best_i0 + best_nx - 1, old_nx, invalid)
          : fmt::format(
                "invalid points: cropped to the largest rectangle of valid points, columns {} to {} and rows {} "
                "to {} of the {}x{} map ({} invalid points in the map)",
                best_i0, best_i0 + best_nx - 1, best_j0, best_j0 + best_ny - 1, old_nx, old_ny, invalid));
}

}  // namespace halfspace::surface
