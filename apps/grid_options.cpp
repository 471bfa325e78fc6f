// --grid and --size into a Grid, with the spacing checked against the same
// range as the lengths: 1e-3 m over 1e9 cells is a spacing of 1e-12 m.
#include "grid_options.hpp"

#include <fmt/format.h>

#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/physical_ranges.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

double spacing(std::string_view axis, double length, std::size_t cells, const std::string& grid_what,
               const std::string& size_what) {
  const double h = length / static_cast<double>(cells);
  return require_in_range(fmt::format("the spacing {} = {:g} m of {} over {}", axis, h, size_what, grid_what), h,
                          kMinLength, kMaxLength, "m");
}

}  // namespace

Grid grid_from_options(std::string_view grid_text, const std::string& grid_what, std::string_view size_text,
                       const std::string& size_what, Boundary boundary) {
  const std::vector<std::size_t> cells = parse_grid_shape(grid_text, grid_what);
  const std::vector<double> lengths = parse_domain_size(size_text, size_what);
  if (cells.size() == 1) {
    if (lengths.size() != 1) {
      throw InputError(fmt::format("{} is invalid for the 1D grid {}: give one length", size_what, grid_what));
    }
    return Grid::line(cells[0], spacing("dx", lengths[0], cells[0], grid_what, size_what), boundary);
  }
  const double length_y = lengths.size() == 2 ? lengths[1] : lengths[0];
  return Grid::plane(cells[0], cells[1], spacing("dx", lengths[0], cells[0], grid_what, size_what),
                     spacing("dy", length_y, cells[1], grid_what, size_what), boundary);
}

}  // namespace halfspace::app
