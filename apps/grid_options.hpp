// The grid of a built-in surface from --grid (cells) and --size (domain, m),
// and its shape's lengths, shared by `solve --geometry` and `generate`.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/grid.hpp"
#include "option_table.hpp"

namespace halfspace::app {

// Cells per axis from `grid_text` ("N" or "NXxNY"), the domain from
// `size_text` ("L" or "LXxLY"; one length on a 2D grid is a square), and the
// spacing size / cells, which must lie in [kMinLength, kMaxLength] like the
// sizes themselves (physical_ranges.hpp). `grid_what` and `size_what` name
// the options with their values for messages ("--grid 256x256"). Throws
// InputError naming them.
Grid grid_from_options(std::string_view grid_text, const std::string& grid_what, std::string_view size_text,
                       const std::string& size_what, Boundary boundary);

// The grid of a built-in geometry from the options `grid` and `size`
// (grid_from_options), each required. Throws InputError naming the missing one.
Grid grid_for_geometry(const GivenOptions& o, const std::optional<std::string>& grid,
                       const std::optional<std::string>& size, Boundary boundary);

// The length option `key` (m): positive and finite, and within the program's
// range of lengths (physical_ranges.hpp). Throws InputError naming it.
double require_length(const GivenOptions& o, std::string_view key, double value);

// A built-in shape and its source text ("sphere (radius = 0.01 m)").
struct BuiltinShape {
  geometry::SurfaceSpec spec;
  std::string source;
};

// The lengths `shape` needs from the options radius, wavelength and amplitude
// (require_length), the others refused; `shape_key` is the option that chose
// it (geometry, kind), named in the messages.
BuiltinShape builtin_shape_from(const GivenOptions& o, std::string_view shape_key, geometry::SurfaceShape shape,
                                const std::optional<double>& radius, const std::optional<double>& wavelength,
                                const std::optional<double>& amplitude);

}  // namespace halfspace::app
