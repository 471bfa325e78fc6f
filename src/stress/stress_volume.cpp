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

void check_depths(const Grid& grid, std::span<const double> depths) {
  check_depths(depths);
  for (const double z : depths) checked_depth(grid, z);
}

namespace {

// The first process (in rank order, hence row order) whose `found` is true,
// or -1 if none is: the same on every process.
int first_process_with(bool found, const linalg::Communicator& comm) {
  const double none = static_cast<double>(comm.size());
  const double first = comm.min(found ? static_cast<double>(comm.rank()) : none);
  return first == none ? -1 : static_cast<int>(first);
}

// `values` of process `from` on every process (the others give zeros).
void share_from(int from, std::span<double> values, const linalg::Communicator& comm) {
  if (comm.rank() != from) std::fill(values.begin(), values.end(), 0.0);
  comm.sum(values);
}

// Throws InputError at the first value of the slice's nine fields (in storage
// order) that is not finite: nothing that overflowed is handed to a writer.
// On several processes, every process throws the one of the first that
// meets such a value. `first_row`: the grid's row of the slice's first.
void require_finite(const StressSlice& slice, const Grid& grid, std::size_t first_row,
                    const linalg::Communicator& comm) {
  const std::array<const std::vector<double>*, kComponentCount + 3> fields = {
      &slice.components[0], &slice.components[1], &slice.components[2], &slice.components[3], &slice.components[4],
      &slice.components[5], &slice.von_mises,     &slice.max_shear,     &slice.hydrostatic};
  // field, cell (of the grid) and value of the first found here
  std::array<double, 3> first{};
  bool found = false;
  for (std::size_t f = 0; f < fields.size() && !found; ++f) {
    const std::vector<double>& field = *fields[f];
    const auto bad = std::find_if(field.begin(), field.end(), [](double v) { return !std::isfinite(v); });
    if (bad == field.end()) continue;
    found = true;
    first = {static_cast<double>(f),
             static_cast<double>(static_cast<std::size_t>(bad - field.begin()) + first_row * grid.nx()), *bad};
  }
  const int from = first_process_with(found, comm);
  if (from < 0) return;
  share_from(from, first, comm);
  const auto f = static_cast<std::size_t>(first[0]);
  const auto cell = static_cast<std::size_t>(first[1]);
  constexpr std::array<const char*, 3> kDerived = {"von_mises", "max_shear", "hydrostatic"};
  const char* name = f < kComponentCount ? kComponentNames[f] : kDerived[f - kComponentCount];
  throw InputError(fmt::format(
      "the stress {} at depth z = {:.6g} m, cell (row {}, column {}) of the {} grid, is {}: the pressure or the "
      "grid's spacing is too large for the stresses to be represented; nothing was written",
      name, slice.depth, cell / grid.nx(), cell % grid.nx(), grid.shape_string(), first[2]));
}

}  // namespace

VonMisesMaximum stresses_by_depth(SubsurfaceStress& stresses, std::span<const double> pressure,
                                  std::span<const double> depths,
                                  const std::function<void(const StressSlice& slice)>& consume) {
  return stresses_by_depth(stresses, SurfaceTractions{pressure, {}, {}}, depths, consume);
}

VonMisesMaximum stresses_by_depth(SubsurfaceStress& stresses, const SurfaceTractions& tractions,
                                  std::span<const double> depths,
                                  const std::function<void(const StressSlice& slice)>& consume) {
  const Grid& grid = stresses.grid();
  check_depths(grid, depths);
  stresses.set_tractions(tractions);
  const std::size_t cells = stresses.local_size();
  const std::size_t first_row = stresses.rows().first;
  const linalg::Communicator& comm = stresses.communicator();
  StressSlice slice;
  for (auto& component : slice.components) component.resize(cells);
  slice.von_mises.resize(cells);
  slice.max_shear.resize(cells);
  slice.hydrostatic.resize(cells);

  VonMisesMaximum maximum;
  bool first = true;
  for (std::size_t d = 0; d < depths.size(); ++d) {
    slice.index = d;
    slice.depth = depths[d];
    slice.in_layer = stresses.in_layer(depths[d]);
    std::array<std::span<double>, kComponentCount> fields;
    for (std::size_t c = 0; c < kComponentCount; ++c) fields[c] = slice.components[c];
    stresses.compute(depths[d], fields);
    const auto& s = slice.components;
    linalg::for_each_index(cells, [&](std::size_t k) {
      const StressTensor tensor{s[0][k], s[1][k], s[2][k], s[3][k], s[4][k], s[5][k]};
      slice.von_mises[k] = von_mises(tensor);
      slice.max_shear[k] = max_shear(tensor);
      slice.hydrostatic[k] = hydrostatic(tensor);
    });
    require_finite(slice, grid, first_row, comm);
    // The first maximum in storage order (depth, then row), so that the
    // reported point depends neither on the thread count nor on the
    // processes: this depth's largest over them, at the first process (in
    // row order) holding it.
    const auto largest = std::max_element(slice.von_mises.begin(), slice.von_mises.end());
    const double here = largest == slice.von_mises.end() ? -1.0 : *largest;  // a process without rows
    const double value = comm.max(here);
    if (first || value > maximum.value) {
      std::array<double, 2> position{};
      if (here == value) {
        const auto cell = static_cast<std::size_t>(largest - slice.von_mises.begin());
        position[0] = static_cast<double>(cell % grid.nx()) * grid.dx();
        position[1] = grid.dimension() == 1 ? 0.0 : static_cast<double>(first_row + cell / grid.nx()) * grid.dy();
      }
      share_from(first_process_with(here == value, comm), position, comm);
      maximum = {value, position[0], position[1], depths[d]};
      first = false;
    }
    consume(slice);
  }
  return maximum;
}

namespace {

StressVolume fill_volume(SubsurfaceStress& stresses, const SurfaceTractions& tractions,
                         std::span<const double> depths) {
  const std::size_t cells = stresses.local_size();
  const std::size_t total = cells * depths.size();
  StressVolume volume;
  volume.depths.assign(depths.begin(), depths.end());
  for (auto& component : volume.components) component.resize(total);
  volume.von_mises.resize(total);
  volume.max_shear.resize(total);
  volume.hydrostatic.resize(total);
  const auto keep = [&](const std::vector<double>& field, std::vector<double>& into, std::size_t d) {
    std::copy(field.begin(), field.end(), into.begin() + static_cast<std::ptrdiff_t>(d * cells));
  };
  volume.max_von_mises = stresses_by_depth(stresses, tractions, depths, [&](const StressSlice& slice) {
    for (std::size_t c = 0; c < kComponentCount; ++c) keep(slice.components[c], volume.components[c], slice.index);
    keep(slice.von_mises, volume.von_mises, slice.index);
    keep(slice.max_shear, volume.max_shear, slice.index);
    keep(slice.hydrostatic, volume.hydrostatic, slice.index);
  });
  return volume;
}

}  // namespace

StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   double nu, FftPlanning planning) {
  check_depths(grid, depths);
  return compute_stress_volume(grid, SurfaceTractions{pressure, {}, {}}, depths, nu, planning);
}

StressVolume compute_stress_volume(const Grid& grid, const SurfaceTractions& tractions, std::span<const double> depths,
                                   double nu, FftPlanning planning) {
  check_depths(grid, depths);
  SubsurfaceStress stresses(grid, nu, planning);
  return fill_volume(stresses, tractions, depths);
}

StressVolume compute_stress_volume(const Grid& grid, std::span<const double> pressure, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning) {
  return compute_stress_volume(grid, SurfaceTractions{pressure, {}, {}}, depths, coating, planning);
}

StressVolume compute_stress_volume(const Grid& grid, const SurfaceTractions& tractions, std::span<const double> depths,
                                   const LayeredMaterial& coating, FftPlanning planning) {
  check_depths(grid, depths);
  SubsurfaceStress stresses(grid, coating, planning);
  StressVolume volume = fill_volume(stresses, tractions, depths);
  volume.coating = coating;
  for (const double z : depths) volume.in_layer.push_back(stresses.in_layer(z));
  return volume;
}

double stress_memory_estimate(const Grid& grid, bool coated, bool shear) {
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  // Periodic: the pressure spectrum, the layout's two transforms (spectra,
  // and the real array of the one used), the decay table (about 6 doubles a
  // cell). Free: the padded pressure spectrum, the layout's two padded
  // transforms (one for the fields, one for the coefficients' wrap-around
  // array), a component's spectrum summed over the tractions (4 doubles a
  // cell each) and the six coefficient quadrants (about 26).
  // Coated: each half-spectrum mode's solution (8 doubles) and profile (3)
  // instead of the decay table, about 5.5 more doubles a cell; on a free
  // grid the remainder's six parts on the padded half spectrum (12).
  // Shear: two more spectra (periodic: about 1 double a cell each; free: the
  // padded one's 4) and, on free grids, two more sets of six quadrants;
  // below a coating each half-spectrum mode's shear solution and its two
  // profiles (periodic: 15 doubles, 7.5 a cell) or the remainder's six
  // parts per shear (free: 24 a cell).
  const double coated_shear = coated ? (grid.periodic() ? 7.5 : 24.0) : 0.0;
  const double shear_workspace = shear ? (grid.periodic() ? 2.0 : 20.0) + coated_shear : 0.0;
  const double workspace =
      ((grid.periodic() ? (coated ? 11.5 : 6.0) : (coated ? 38.0 : 26.0)) + shear_workspace) * 8.0 * cells;
  // The pressure itself and one depth's nine fields.
  constexpr double kSliceFields = 9.0;
  return 8.0 * cells + workspace + kSliceFields * 8.0 * cells;
}

}  // namespace halfspace::stress
