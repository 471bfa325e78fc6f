// The influence operator's defaults (influence_operator.hpp).
#include "halfspace/operators/influence_operator.hpp"

#include "halfspace/operators/spectral_transforms.hpp"

namespace halfspace::operators {

std::unique_ptr<SpectralTransforms> InfluenceOperator::transforms_for(const Grid& grid) const {
  return make_serial_transforms(grid, FftPlanning::estimate, {.count = 1});
}

}  // namespace halfspace::operators
