// What to do with the invalid points of a measured height map (dropouts that
// the instrument marked, or non-finite values): refuse, fill or crop.
#pragma once

#include <string_view>

#include "halfspace/height_map.hpp"
#include "halfspace/linalg/communicator.hpp"

namespace halfspace::surface {

enum class InvalidPoints {
  refuse,  // any invalid point is an error
  fill,    // trim fully invalid border rows/columns, then fill by harmonic interpolation
  crop,    // keep the largest rectangle of valid points
};

std::string_view to_string(InvalidPoints policy);
// "refuse", "fill" or "crop"; throws InputError naming the value otherwise.
InvalidPoints parse_invalid_points(std::string_view text);

// Number of invalid points (0 when map.valid is empty).
std::size_t count_invalid(const HeightMap& map);

// Throws FileError naming map.source, the number of invalid points and the
// first one (row j, column i) when there is any; does nothing otherwise.
void refuse_invalid_points(const HeightMap& map);

// The same for a map spread over processes in slabs of rows (map.ny the
// whole map's, map.valid this process's rows from first_row on): the count
// and the first point are the whole map's, found over `comm`, so every
// process throws the serial message or none does.
void refuse_invalid_points_rows(const HeightMap& map, std::size_t first_row, const linalg::Communicator& comm);

// Fills the invalid points: first the rows and columns at the edges that hold
// no valid point at all are cut off (there is nothing to interpolate from;
// this is how the topography README cropped KautschukInfiniteFocus), then
// every remaining invalid point is set to the discrete harmonic (Laplace)
// interpolant of the valid points: the 5-point Laplacian, weighted 1/dx^2 and
// 1/dy^2 (1 where a spacing is 0), is zero at invalid points, with the valid
// points fixed and zero flux across the map's edges. A plane is reproduced
// exactly. Solved directly (sparse Cholesky) in the invalid points only.
// Clears map.valid and appends a line to map.preparation. Throws InputError
// when no point is valid or the trimmed map has fewer than 2 points per axis.
void fill_invalid_points(HeightMap& map);

// Keeps the largest axis-aligned rectangle (most points; among equals the
// one with the smallest top row, then the smallest left column) that holds
// only valid points; for a profile, the longest run of valid points. Clears
// map.valid and appends a line to map.preparation. Throws InputError when
// that rectangle has fewer than 2 points along an axis.
void crop_to_valid_points(HeightMap& map);

}  // namespace halfspace::surface
