// Writes a solve's fields and summary to an HDF5 file (the result contract,
// docs/file-format.md). The file appears only when complete: it is written
// under a temporary name in the same directory and renamed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/layered_material.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "halfspace/surface/statistics.hpp"

namespace halfspace::io {

struct ResultMetadata {
  double e_star = 0.0;    // Pa
  std::string load_mode;  // "force", "mean_pressure" or "approach"
  int threads = 1;
  std::string command_line;   // the full command line
  std::string config;         // the TOML config text, empty if none
  std::string height_source;  // where the surface came from
  std::string preparation;    // the preparation steps applied to it, one per line; empty if none
  // Written as root attributes when given: mean_gap, rms_gap, free_volume,
  // clusters; surface_rms_height, surface_rms_slope (docs/file-format.md).
  std::optional<analysis::ContactStatistics> contact_statistics;
  std::optional<surface::SurfaceStatistics> surface_statistics;
  // More groups written under the root after the fields when set (the
  // /stress group of solve --stress-depths).
  std::function<void(const Hdf5Node& root)> extra_groups;
  // An upper bound on the bytes extra_groups adds (stress_group_bound). When
  // not 0 the file is written in place (write_large_hdf5_file) instead of in
  // memory, so that a large group is never held whole.
  std::uint64_t extra_groups_bytes = 0;
  // A coated half-space: its five constants as root attributes (layer_thickness,
  // layer_E, layer_nu, substrate_E, substrate_nu); e_star is then the layer's
  // E1/(1 - nu1^2), its modulus against the rigid surface.
  std::optional<LayeredMaterial> coating;
  // Both bodies, when they were given (E1, nu1, E2, nu2; not a coated one):
  // root attributes body1_E, body1_nu, body2_E, body2_nu (E2 = inf for a
  // rigid body 2), from which `halfspace stress` takes whose stresses and
  // the Poisson's ratio.
  std::optional<ElasticPair> bodies;
  // Friction: a tangential load step whose fields (shear_x, shear_y, stick,
  // slip_x, slip_y, tangential_displacement_x, _y) and attributes
  // (result_attributes.hpp's tangential table) the result also holds; must
  // outlive the write. Null: a frictionless result.
  const TangentialResult* tangential = nullptr;
  // A coupled friction history (dissimilar bodies): each step's own normal
  // solution (its pressure under its shear), one per step, written into the
  // step's group (write_friction_history); must outlive the write. Empty:
  // every step has the root's pressure.
  std::vector<const SolveResult*> step_normals;
};

// Datasets /height, /pressure, /gap, /displacement (float64) and /contact
// (uint8, 1 where p > 0), shaped like the grid, with the friction fields and
// attributes when metadata.tangential is set; root attributes as in
// docs/file-format.md. Throws FileError naming the path if it cannot be
// written; no partial file is left behind.
void write_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                  const SolveResult& result, const ResultMetadata& metadata);

// An upper bound on the bytes of write_result's file (reserve_output_space),
// so that a full disk or a file-size limit is met before any field is
// written (by write_result with extra groups, and by the collective writer,
// where a process failing alone in mid-write would leave the others waiting).
std::uint64_t result_file_bound(const Grid& grid, const SolveResult& result, const ResultMetadata& metadata);

// Files whose bound (result_file_bound) is at most this are assembled in
// memory and written in one piece; larger ones are written in place, since
// assembling in memory holds the file twice (HDF5's buffer and its image),
// which would set the peak memory of a large solve.
inline constexpr std::uint64_t kInMemoryResultBytes = std::uint64_t{64} << 20;

}  // namespace halfspace::io
