// Writes a tangential load history (more than one step of a frictional
// solve): one HDF5 file with the normal contact's fields, a group of friction
// fields per step and the history table, and the same table as CSV beside it
// (docs/file-format.md#friction-histories). Both appear only when complete,
// written as one set (output_file.hpp's write_output_set), like a sweep's.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::io {

// Root: /height and the normal result's fields and attributes (as a single
// result), with the last step's friction fields and attributes, plus
// history_steps and history_csv_md5 (the MD5 of the CSV);
// /steps/NNN (zero-padded, at least 3 digits): the step's friction fields
// and attributes, and tangential_control ("force" or "displacement"),
// tangential_load_x, _y (what was imposed), and with metadata.step_normals
// (a coupled history) the step's own normal fields and attributes (pressure,
// gap, displacement, contact, residual_history, total_force, ...) as a
// single result's root holds them; /history/<column> (float64, one
// entry per step) for every column of the CSV. The CSV, at
// history_csv_path(path), has the columns step, Q_x, Q_y, delta_x, delta_y,
// stick_fraction, dissipated_energy (N or N/m, m, J or J/m in 1D; the
// dissipated energy is the sum over cells of -q . ds times the cell area in
// that step). metadata.tangential is ignored. Throws InputError if `steps`
// is empty, `loads` or metadata.step_normals (when given) has another
// length, or a field does not match the grid;
// FileError naming the path if a file cannot be written.
void write_friction_history(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                            const SolveResult& normal, std::span<const TangentialResult> steps,
                            std::span<const TangentialLoading> loads, const ResultMetadata& metadata);

// The history table as CSV text: a header line, then one line per step,
// numbers in the shortest form that reads back exactly.
std::string friction_history_csv(std::span<const TangentialResult> steps);

// Where the CSV of a history written to `result_path` goes: the same name
// with the extension .csv (loop.h5 -> loop.csv).
std::filesystem::path history_csv_path(const std::filesystem::path& result_path);

}  // namespace halfspace::io
