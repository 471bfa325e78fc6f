// Height maps made from a function, and the messages of refused steps, for
// the surface preparation tests.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <functional>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/height_map.hpp"

namespace halfspace::testing {

// An nx x ny map (ny = 1: a profile) of spacing dx, dy whose heights are
// f(x, y) at x = (i + offset) dx, y = (j + offset) dy: offset 0 samples the
// nodes, 1/2 the cells' centres.
inline HeightMap sampled_map(std::size_t nx, std::size_t ny, double dx, double dy,
                             const std::function<double(double, double)>& f, double offset = 0.0) {
  HeightMap map;
  map.dimension = ny == 1 ? 1 : 2;
  map.nx = nx;
  map.ny = ny;
  map.dx = dx;
  map.dy = ny == 1 ? 0.0 : dy;
  map.source = "synthetic";
  map.heights.resize(static_cast<Eigen::Index>(nx * ny));
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      map.heights[static_cast<Eigen::Index>(j * nx + i)] =
          f((static_cast<double>(i) + offset) * dx, (static_cast<double>(j) + offset) * dy);
    }
  }
  return map;
}

// The message of the InputError that step() throws; no exception is a
// test failure.
inline std::string input_error_of(const std::function<void()>& step) {
  try {
    step();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

}  // namespace halfspace::testing
