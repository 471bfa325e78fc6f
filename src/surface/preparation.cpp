// The preparation steps in their fixed order (see preparation.hpp for why).
#include "halfspace/surface/preparation.hpp"

#include "halfspace/surface/padding.hpp"

namespace halfspace::surface {

void prepare_height_map(HeightMap& map, const PreparationOptions& options) {
  if (options.window) select_window(map, *options.window);
  if (options.invalid == InvalidPoints::crop) crop_to_valid_points(map);
  if (options.invalid == InvalidPoints::refuse) refuse_invalid_points(map);
  detrend(map, options.detrend);
  if (options.invalid == InvalidPoints::fill) fill_invalid_points(map);
  if (options.resample) resample(map, *options.resample);
  if (options.pad_factor != 1.0) pad_for_free_boundary(map, options.pad_factor);
}

}  // namespace halfspace::surface
