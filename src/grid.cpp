// Grid construction and validation: at least 2 cells per axis, at most
// kMaxGridCells in all (checked_size.hpp), and spacings, cell area and domain
// area positive, finite and normal, so that no size or area derived from a
// grid overflows or underflows.
#include "halfspace/grid.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "halfspace/checked_size.hpp"
#include "halfspace/error.hpp"

namespace halfspace {
namespace {

void check_cells(std::string_view name, std::size_t n) {
  if (n < 2) {
    throw InputError(fmt::format("grid size {} = {} is too small: need at least 2 cells", name, n));
  }
}

void check_spacing(std::string_view name, double h) {
  if (!(std::isnormal(h) && h > 0.0)) {
    throw InputError(
        fmt::format("grid spacing {} = {} m is invalid: must be positive, finite and not denormal", name, h));
  }
}

// Counts of cells beyond kMaxGridCells would overflow the byte counts of the
// arrays made on the grid (checked_size.hpp).
void check_cell_count(std::size_t nx, std::size_t ny) {
  const std::optional<std::size_t> cells = checked_multiply(nx, ny);
  if (!cells || *cells > kMaxGridCells) {
    throw InputError(fmt::format("grid {}x{} is too large: nx * ny = {:.4g} cells, at most {} are allowed", nx, ny,
                                 static_cast<double>(nx) * static_cast<double>(ny), kMaxGridCells));
  }
}

// Areas must be usable as divisors and factors: a product of two tiny
// spacings can underflow to 0, one of two huge ones overflow to infinity.
void check_area(std::string_view name, double area, std::string_view unit) {
  if (!(std::isnormal(area) && area > 0.0)) {
    throw InputError(
        fmt::format("grid {} = {} {} is invalid: must be positive, finite and not denormal", name, area, unit));
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
  check_cell_count(n, 1);
  check_spacing("dx", dx);
  check_area("length n * dx", static_cast<double>(n) * dx, "m");
  return Grid(1, n, 1, dx, 0.0, boundary);
}

Grid Grid::plane(std::size_t nx, std::size_t ny, double dx, double dy, Boundary boundary) {
  check_cells("nx", nx);
  check_cells("ny", ny);
  check_cell_count(nx, ny);
  check_spacing("dx", dx);
  check_spacing("dy", dy);
  check_area("cell area dx * dy", dx * dy, "m^2");
  check_area("area", dx * dy * static_cast<double>(nx) * static_cast<double>(ny), "m^2");
  return Grid(2, nx, ny, dx, dy, boundary);
}

std::string Grid::shape_string() const {
  return dimension_ == 1 ? fmt::format("{}", nx_) : fmt::format("{}x{}", nx_, ny_);
}

void check_field_size(std::string_view what, std::size_t size, const Grid& grid) {
  check_field_size(what, size, grid, grid.size());
}

void check_field_size(std::string_view what, std::size_t size, const Grid& grid, std::size_t held) {
  if (size == held) return;
  if (held == grid.size()) {
    throw InputError(
        fmt::format("{} has {} values but the grid has {} cells ({})", what, size, held, grid.shape_string()));
  }
  throw InputError(
      fmt::format("{} has {} values but {} cells of the {} grid are held here", what, size, held, grid.shape_string()));
}

}  // namespace halfspace
