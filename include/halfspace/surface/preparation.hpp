// The preparation of a measured height map before contact, as one call:
// window, invalid points, detrending, resampling and padding, in that order.
#pragma once

#include <optional>

#include "halfspace/height_map.hpp"
#include "halfspace/surface/detrend.hpp"
#include "halfspace/surface/invalid_points.hpp"
#include "halfspace/surface/resample.hpp"
#include "halfspace/surface/window.hpp"

namespace halfspace::surface {

struct PreparationOptions {
  std::optional<Window> window;                   // none: the whole map
  InvalidPoints invalid = InvalidPoints::refuse;  // what to do with invalid points
  Detrend detrend = Detrend::none;
  std::optional<Resample> resample;  // none: the map's own cells
  double pad_factor = 1.0;           // > 1 pads for free boundaries (the caller rejects it with periodic ones)
};

// Applies, in this order: the window (in the indices of the file); then
// `crop` or `refuse` for invalid points; the detrending, fitted to the valid
// points only; `fill` (after detrending, so that the fill interpolates the
// detrended surface and the fit never sees invented heights); the
// resampling (it needs a height at every point); the padding.
// Each step that changes the map appends one line to map.preparation. After
// it the map has no invalid points. Throws InputError/FileError as the steps
// do.
void prepare_height_map(HeightMap& map, const PreparationOptions& options);

}  // namespace halfspace::surface
