// Writes the stresses below a contact (halfspace/stress/stress_volume.hpp) to
// HDF5: the `/stress` group of a result file, or a file of its own made by the
// `stress` command (layout in docs/file-format.md#stress-output). The
// stresses are computed and written one depth at a time, so that memory holds
// one depth's fields, never the volume.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/stress/surface_traction.hpp"

namespace halfspace::io {

// Under `root`: the group `stress` with `depths` (m, (nz)) and sigma_xx,
// sigma_yy, sigma_zz, sigma_xy, sigma_xz, sigma_yz, von_mises, max_shear,
// hydrostatic (Pa, (nz, ny, nx); 1D (nz, n)), the group attribute
// poisson_ratio, and the root attributes max_von_mises (Pa) and its position
// max_von_mises_x, _y, _z (m). Below a coating also `in_layer` ((nz), 1 for a
// depth in the layer, 0 in the substrate) and the attributes layer_thickness
// (m), layer_poisson_ratio and substrate_poisson_ratio. The fields are those
// of `pressure` on `stresses`' grid at `depths` (stresses_by_depth), written
// depth by depth. Returns the largest von Mises stress and its position.
stress::VonMisesMaximum write_stress_group(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                           std::span<const double> pressure, std::span<const double> depths);
// The same under the pressure and the shear tractions beside it
// (stress/surface_traction.hpp: q on the body whose stresses these are, Pa;
// a friction result's /shear_x and /shear_y). The group's string attribute
// `tractions` says which were used ("pressure" or "pressure and shear").
// Throws InputError for a shear on a coated half-space.
stress::VonMisesMaximum write_stress_group(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                           const stress::SurfaceTractions& tractions, std::span<const double> depths);

// An upper bound on the bytes the /stress group adds to a file.
std::uint64_t stress_group_bound(const Grid& grid, std::size_t depth_count);

// Has the result file written with `metadata` hold the /stress group
// (extra_groups and its bound): the stresses at `depths` of `body` (with its
// Poisson's ratio), or of the coated half-space below `coating`, under
// `on_body2` (a result's pressure and shear, the tractions on body 2; body 1
// takes -q, tractions_on), computed depth by depth on this process's rows
// of `layout` while the file is written. `on_body2`'s fields must outlive
// the write. Throws InputError for what SubsurfaceStress refuses.
void attach_stress_group(ResultMetadata& metadata, const Grid& grid, const std::optional<LayeredMaterial>& coating,
                         const stress::StressedBodyChoice& body, const stress::SurfaceTractions& on_body2,
                         std::span<const double> depths, const solvers::Layout& layout, FftPlanning planning);

struct StressFileMetadata {
  std::string source;        // the result file the pressure came from
  std::string command_line;  // the full command line
};

// A file of its own: root attributes format ("halfspace-stress"), the grid
// (dimension, nx, ny, dx, dy, boundary) and provenance, the `/pressure` the
// stresses come from, and the `/stress` group. Written in place under its
// temporary name (write_large_hdf5_file), then renamed: atomic like every
// output (output_file.hpp); throws FileError naming the path.
stress::VonMisesMaximum write_stress_file(const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                                          std::span<const double> pressure, std::span<const double> depths,
                                          const StressFileMetadata& metadata);
// The same under the pressure and shear tractions; the file then also holds
// the `/shear_x` and `/shear_y` they come from (a zero field for an empty span).
stress::VonMisesMaximum write_stress_file(const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                                          const stress::SurfaceTractions& tractions, std::span<const double> depths,
                                          const StressFileMetadata& metadata);

// What write_stress_file writes under `root`: on a distributed layout each
// process its rows() of every field (the tractions hold them), the file
// being written by all of them at once (mpi::write_file_slabs). Returns the
// largest von Mises stress and its position.
stress::VonMisesMaximum write_stress_file_contents(const Hdf5Node& root, stress::SubsurfaceStress& stresses,
                                                   const stress::SurfaceTractions& tractions,
                                                   std::span<const double> depths, const StressFileMetadata& metadata);
// An upper bound on the bytes of write_stress_file's file.
std::uint64_t stress_file_bound(const Grid& grid, bool shear, std::size_t depth_count);

}  // namespace halfspace::io
