// The grid of a built-in surface from --grid (cells) and --size (domain, m),
// shared by `solve --geometry` and `generate`.
#pragma once

#include <string>
#include <string_view>

#include "halfspace/grid.hpp"

namespace halfspace::app {

// Cells per axis from `grid_text` ("N" or "NXxNY"), the domain from
// `size_text` ("L" or "LXxLY"; one length on a 2D grid is a square), and the
// spacing size / cells, which must lie in [kMinLength, kMaxLength] like the
// sizes themselves (physical_ranges.hpp). `grid_what` and `size_what` name
// the options with their values for messages ("--grid 256x256"). Throws
// InputError naming them.
Grid grid_from_options(std::string_view grid_text, const std::string& grid_what, std::string_view size_text,
                       const std::string& size_what, Boundary boundary);

}  // namespace halfspace::app
