// The rigid film: heights below a flat at a separation.
#include "halfspace/lubrication/film.hpp"

#include <fmt/format.h>

#include <cmath>

#include "halfspace/error.hpp"

namespace halfspace::lubrication {

Eigen::ArrayXd film_thickness(const Grid& grid, const Eigen::ArrayXd& heights, double separation) {
  if (static_cast<std::size_t>(heights.size()) != grid.size()) {
    throw InputError(fmt::format("heights have {} values, the {} grid has {} cells", heights.size(),
                                 grid.shape_string(), grid.size()));
  }
  return film_thickness(heights, heights.size() > 0 ? heights.maxCoeff() : 0.0, separation);
}

Eigen::ArrayXd film_thickness(const Eigen::ArrayXd& heights, double highest, double separation) {
  if (!(std::isfinite(separation) && separation > 0.0)) {
    throw OptionError("separation", format_number(separation) + " m", "is invalid: it must be positive and finite");
  }
  if (!heights.allFinite() || !std::isfinite(highest)) {
    throw InputError("heights are invalid: every height must be finite");
  }
  return separation + (highest - heights);
}

}  // namespace halfspace::lubrication
