// Removing the mean, a plane (tilt) or a quadratic (curvature) from a
// measured height map by least squares over its valid points.
#pragma once

#include <string_view>

#include "halfspace/height_map.hpp"
#include "halfspace/linalg/communicator.hpp"

namespace halfspace::surface {

enum class Detrend {
  none,       // heights as read
  mean,       // subtract the mean height
  plane,      // subtract the least-squares plane a + b x + c y (a + b x for a profile)
  curvature,  // subtract the least-squares quadratic a + b x + c y + d x^2 + e x y + f y^2
};

std::string_view to_string(Detrend detrend);
// "none", "mean", "plane" (alias "tilt"), "curvature" (alias "quadratic").
// Throws InputError naming the value and the choices.
Detrend parse_detrend(std::string_view text);

// Subtracts the least-squares fit of `detrend` over the valid points (at
// x = i dx, y = j dy) from every valid point; invalid points stay NaN. The
// removed surface does not depend on dx and dy (scaling an axis maps planes
// to planes and quadratics to quadratics); they only set the units of the
// coefficients reported in the line appended to map.preparation (per cell
// when a spacing is 0). Exact for heights that are such a polynomial, to
// rounding. Throws InputError when the valid points cannot determine the fit
// (e.g. a plane through points on one line).
void detrend(HeightMap& map, Detrend detrend);

// The same for a map spread over processes in slabs of rows: map.ny is the
// whole map's, map.heights (and map.valid) hold this process's rows from
// first_row on. The fit's sums are added over `comm`, so every process
// subtracts the same surface and appends the same line (the serial fit's to
// rounding: the sums are added in another order).
void detrend_rows(HeightMap& map, Detrend detrend, std::size_t first_row, const linalg::Communicator& comm);

}  // namespace halfspace::surface
