// Writes a load sweep: one HDF5 file with a group of fields per step and the
// summary table (docs/file-format.md#sweep-results), and the same table as
// CSV. Both files appear only when complete (temporary name, then rename),
// written as one set (output_file.hpp's write_output_set).
#pragma once

#include <filesystem>
#include <span>

#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/io/result_writer.hpp"

namespace halfspace::io {

// Root: the attributes of a single result for the last step (with its
// contact statistics and metadata.surface_statistics), plus sweep_steps;
// /height; /steps/NNN (zero-padded, at least 3 digits) with pressure, gap,
// displacement, contact, residual_history and cluster_sizes (int64, largest
// first) and the step's attributes; /sweep/<column> (float64, one entry per
// step) for every summary_columns() column (sweep_table.hpp). metadata.load_mode and
// the rest of metadata apply to every step; the root attribute
// summary_csv_md5 is the MD5 of the summary table's CSV. The CSV is written
// with it to sweep_csv_path(path): both temporaries complete first, then the
// previous CSV removed, the .h5 renamed, the .csv renamed, so that the two
// never come from different sweeps. Throws InputError if `steps` is empty or
// a field does not match the grid, FileError naming the path if a file cannot
// be written.
void write_sweep_result(const std::filesystem::path& path, const Grid& grid, std::span<const double> height,
                        std::span<const analysis::SweepStep> steps, const ResultMetadata& metadata);

// The summary table as CSV: a header line of the column names, then one line
// per step, numbers in the shortest form that reads back exactly (what
// write_sweep_result writes beside its file; for writers of the .h5 that
// write the CSV apart, the MPI one). Throws
// FileError naming the path if it cannot be written.
void write_sweep_csv(const std::filesystem::path& path, std::span<const analysis::SweepStep> steps);

// Where the CSV of a sweep written to `result_path` goes: the same name with
// the extension .csv (sweep.h5 -> sweep.csv).
std::filesystem::path sweep_csv_path(const std::filesystem::path& result_path);

}  // namespace halfspace::io
