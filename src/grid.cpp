// Grid construction and validation.
#include "halfspace/grid.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

void check_cells(std::string_view name, std::size_t n) {
  if (n < 2) {
    throw InputError(fmt::format("grid size {} = {} is too small: need at least 2 cells", name, n));
  }
}

void check_spacing(std::string_view name, double h) {
  if (!(std::isfinite(h) && h > 0.0)) {
    throw InputError(fmt::format("grid spacing {} = {} m is invalid: must be positive and finite", name, h));
  }
}

}  // namespace

std::string_view to_string(Boundary boundary) {
  return boundary == Boundary::periodic ? "periodic" : "free";
}

Boundary parse_boundary(std::string_view text) {
  if (text == "periodic") return Boundary::periodic;
  if (text == "free") return Boundary::free;
  throw InputError(fmt::format("boundary '{}' is not known: use 'periodic' or 'free'", text));
}

Grid Grid::line(std::size_t n, double dx, Boundary boundary) {
  check_cells("n", n);
  check_spacing("dx", dx);
  return Grid(1, n, 1, dx, 0.0, boundary);
}

Grid Grid::plane(std::size_t nx, std::size_t ny, double dx, double dy, Boundary boundary) {
  check_cells("nx", nx);
  check_cells("ny", ny);
  check_spacing("dx", dx);
  check_spacing("dy", dy);
  return Grid(2, nx, ny, dx, dy, boundary);
}

std::string Grid::shape_string() const {
  return dimension_ == 1 ? fmt::format("{}", nx_) : fmt::format("{}x{}", nx_, ny_);
}

}  // namespace halfspace
