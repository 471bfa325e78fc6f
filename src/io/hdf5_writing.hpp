// Private: the parts of the result layout (docs/file-format.md) that the
// single-result writer and the sweep writer share, defined in
// result_writer.cpp. The HDF5 conventions themselves are public, in
// halfspace/io/hdf5_output.hpp.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "halfspace/grid.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::io {

// The bytes of the file write_hdf5_file would write to `path` (checked as an
// output path first), for a writer that writes it with other files as one
// set (write_output_set). Throws FileError "cannot write output '<path>': ...".
std::vector<char> hdf5_file_image(const std::filesystem::path& path,
                                  const std::function<void(const Hdf5Node& root)>& fill);

// Which rows of the fields a writer holds: all of them (the serial
// writers), or, in a file that several processes write at once, this
// process's rows from first_row on; the `lead` process writes the datasets
// that are not fields (residual_history).
struct FieldRows {
  std::size_t first_row = 0;
  bool lead = true;
};

// The datasets pressure, gap, displacement (float64, shaped like the grid),
// contact (uint8, 1 where p > 0) and residual_history under `node`; the
// result's fields hold the rows `rows` says.
void write_result_fields(const Hdf5Node& node, const Grid& grid, const SolveResult& result, FieldRows rows = {});

// Friction: shear_x, shear_y (Pa), stick (uint8, 1 where a contact cell
// sticks), slip_x, slip_y (accumulated slip, m) and
// tangential_displacement_x, _y (m) of a tangential step under `node`.
void write_tangential_fields(const Hdf5Node& node, const Grid& grid, const TangentialResult& result,
                             FieldRows rows = {});

// The root attributes of a result file: format, grid, E*, load mode, every
// result attribute (result_attributes.hpp), threads, provenance and the
// statistics given in `metadata`.
void write_result_root_attributes(const Hdf5Node& root, const Grid& grid, const SolveResult& result,
                                  const ResultMetadata& metadata);

// A single result's datasets and attributes (write_result's file; with
// metadata.tangential the friction fields and attributes too), `height` and
// the fields holding the rows `rows` says.
void write_result_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                           const SolveResult& result, const ResultMetadata& metadata, FieldRows rows = {});

// A friction history's datasets and attributes (write_friction_history's
// file without its CSV, whose text is `csv`), the fields holding the rows
// `rows` says.
void write_friction_history_contents(const Hdf5Node& root, const Grid& grid, std::span<const double> height,
                                     const SolveResult& normal, std::span<const TangentialResult> steps,
                                     std::span<const TangentialLoading> loads, const ResultMetadata& metadata,
                                     const std::string& csv, FieldRows rows = {});

}  // namespace halfspace::io
