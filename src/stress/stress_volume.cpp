// The stresses at every requested depth, then the derived fields per point.
#include "halfspace/stress/stress_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/stress/stress_tensor.hpp"
#include "halfspace/stress/subsurface_stress.hpp"

namespace halfspace::stress {

void check_depths(std::span<const double> depths) {
  if (depths.empty()) throw InputError("no depth given: at least one depth (m, > 0) is needed for stresses");
  if (depths.size() > kMaxDepthCount) {
    throw InputError(
        fmt::format("{} depths requested: allowed range is 1 to {} depths", depths.size(), kMaxDepthCount));
  }
  for (const double z : depths) checked_depth(z);
}

namespace {

StressVolume fill_volume(SubsurfaceStress& stresses, std::span<const double> pressure, std::span<const double> depths) {
  const Grid& grid = stresses.grid();
  stresses.set_pressure(pressure);
  const std::size_t cells = grid.size();
  const std::size_t total = cells * depths.size();
  StressVolume volume;
  volume.depths.assign(depths.begin(), depths.end());
  for (auto& component : volume.components) component.resize(total);
  volume.von_mises.resize(total);
  volume.max_shear.resize(total);
  volume.hydrostatic.resize(total);

  for (std::size_t d = 0; d < depths.size(); ++d) {
    std::array<std::span<double>, kComponentCount> fields;
    for (std::size_t c = 0; c < kComponentCount; ++c) {
      fields[c] = std::span<double>(volume.components[c]).subspan(d * cells, cells);
    }
    stresses.compute(depths[d], fields);
  }

  const auto& s = volume.components;
  linalg::for_each_index(total, [&](std::size_t k) {
    const StressTensor tensor{s[0][k], s[1][k], s[2][k], s[3][k], s[4][k], s[5][k]};
    volume.von_mises[k] = von_mises(tensor);
    volume.max_shear[k] = max_shear(tensor);
    volume.hydrostatic[k] = hydrostatic(tensor);
  });

  // The first maximum in storage order, so the reported point does not depend
  // on the thread count.
  const auto largest = std::max_element(volume.von_mises.begin(), volume.von_mises.end());
  const auto index = static_cast<std::size_t>(largest - volume.von_mises.begin());
  const std::size_t cell = index % cells;
  volume.max_von_mises.value = *largest;
  volume.max_von_mises.x = static_cast<double>(cell % grid.nx()) * grid.dx();
  volume.max_von_mises.y = grid.dimension() == 1 ? 0.0 : static_cast<double>(cell / grid.nx()) * grid.dy();
  volume.max_von_mises.z = depths[index / cells];
  return volume;
}

}  // namespace

StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   double nu, FftPlanning planning) {
  check_depths(depths);
  SubsurfaceStress stresses(grid, nu, planning);
  return fill_volume(stresses, pressure, depths);
}

StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning) {
  check_depths(depths);
  SubsurfaceStress stresses(grid, coating, planning);
  StressVolume volume = fill_volume(stresses, pressure, depths);
  volume.coating = coating;
  for (const double z : depths) volume.in_layer.push_back(stresses.in_layer(z));
  return volume;
}

double stress_memory_estimate(const Grid& grid, std::size_t depth_count, bool coated) {
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  constexpr double kStoredFields = 9.0;
  const double volume = kStoredFields * 8.0 * cells * static_cast<double>(depth_count);
  // Periodic: the pressure spectrum, the transform's spectrum and real array,
  // the decay table (about 5 doubles a cell). Free: the padded pressure
  // spectrum and transform, the padded coefficient transform (4 cells each
  // of spectrum and real array) and the six coefficient quadrants (about 26).
  // Coated: each half-spectrum mode's solution (8 doubles) and profile (3)
  // instead of the decay table, about 5.5 more doubles a cell.
  const double workspace = (grid.periodic() ? (coated ? 10.5 : 5.0) : 26.0) * 8.0 * cells;
  // The pressure itself, then the file the writer assembles in memory: HDF5's
  // image of the (uncompressed) fields and its copy, twice the volume
  // (measured peak at 512^2 and 16 depths: 917 MB, 3.0 times the volume).
  return 8.0 * cells + volume + std::max(workspace, 2.0 * volume);
}

}  // namespace halfspace::stress
