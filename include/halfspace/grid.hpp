// The computational grid: 1D (n cells) or 2D (nx x ny cells), cell spacings and
// boundary type. Fields on a 2D grid are stored (ny, nx) row-major:
// f[j * nx + i] = f(x = i * dx, y = j * dy). A 1D grid has ny = 1 and dy = 0.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace halfspace {

enum class Boundary {
  periodic,  // the surface repeats with period nx*dx (and ny*dy)
  free,      // non-periodic: an isolated patch on an infinite half-space
};

std::string_view to_string(Boundary boundary);
// Parses "periodic" or "free"; throws InputError naming the value otherwise.
Boundary parse_boundary(std::string_view text);

class Grid {
 public:
  // A 1D grid of n cells of width dx (m). Throws InputError if n < 2 or dx <= 0.
  static Grid line(std::size_t n, double dx, Boundary boundary);
  // A 2D grid of nx x ny cells of dx x dy (m). Throws InputError if nx < 2,
  // ny < 2, or a spacing is not positive and finite.
  static Grid plane(std::size_t nx, std::size_t ny, double dx, double dy, Boundary boundary);

  int dimension() const { return dimension_; }
  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  Boundary boundary() const { return boundary_; }
  bool periodic() const { return boundary_ == Boundary::periodic; }

  // Number of cells, nx * ny.
  std::size_t size() const { return nx_ * ny_; }
  // Cell area dx*dy in m^2; in 1D the cell width dx in m, so that a sum of
  // pressure times cell_area() is a force (N in 2D, N/m in 1D).
  double cell_area() const { return dimension_ == 1 ? dx_ : dx_ * dy_; }
  // Domain area (m^2), or domain length (m) in 1D.
  double domain_area() const { return cell_area() * static_cast<double>(size()); }
  // "512" or "512x256" (nx x ny).
  std::string shape_string() const;

 private:
  Grid(int dimension, std::size_t nx, std::size_t ny, double dx, double dy, Boundary boundary)
      : dimension_(dimension), nx_(nx), ny_(ny), dx_(dx), dy_(dy), boundary_(boundary) {}

  int dimension_;
  std::size_t nx_;
  std::size_t ny_;
  double dx_;
  double dy_;
  Boundary boundary_;
};

// Throws InputError unless the field `what` ("initial gap", "write_result:
// field 'gap'") holds one value per cell of `grid`, or with `held`, one per
// cell this process holds of it (its slab of rows; all of them on one
// process). The message names the field, its count and the count expected,
// with "here" when that is a slab's.
void check_field_size(std::string_view what, std::size_t size, const Grid& grid);
void check_field_size(std::string_view what, std::size_t size, const Grid& grid, std::size_t held);

}  // namespace halfspace
