// The collective write: the serial writers' datasets and attributes
// (io/hdf5_writing.hpp, io/height_map_writer.hpp) into one file opened by every process with MPI-IO,
// field datasets by rows, attributes and small datasets alike everywhere
// (the parallel HDF5 needs every process to make the same metadata calls).
#include "halfspace/mpi/parallel_result_writer.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "../io/hdf5_handle.hpp"
#include "../io/hdf5_writing.hpp"
#include "../io/sweep_writing.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/friction_history_writer.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/mpi/agreement.hpp"

namespace halfspace::mpi {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw FileError(fmt::format("cannot write output '{}': {}: {}", path.string(), what, io::detail::error_reason()));
}

// The temporary, created by every process with MPI-IO (collective).
io::detail::File create_collectively(const MpiCommunicator& comm, const std::filesystem::path& path,
                                     const std::string& temporary) {
  const io::detail::ErrorPrintingOff quiet;
  const io::detail::PropertyList access(H5Pcreate(H5P_FILE_ACCESS));
  if (!access.valid() || H5Pset_fapl_mpio(access.get(), comm.get(), MPI_INFO_NULL) < 0) {
    fail(path, "could not set up the parallel HDF5 writing");
  }
  io::detail::File file(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
  if (!file.valid()) fail(path, fmt::format("could not create temporary file '{}'", temporary));
  return file;
}

void write_into(io::detail::File& file, const std::filesystem::path& path, const std::string& temporary,
                const std::function<void(const io::Hdf5Node& root)>& fill) {
  const io::detail::ErrorPrintingOff quiet;
  const io::detail::PropertyList transfer(H5Pcreate(H5P_DATASET_XFER));
  if (!transfer.valid() || H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) < 0) {
    fail(path, "could not set up the parallel HDF5 writing");
  }
  try {
    io::fill_hdf5_file(file.get(), transfer.get(), fill);
  } catch (const FileError& error) {
    throw FileError(fmt::format("cannot write output '{}': {}", path.string(), error.what()));
  }
  if (!file.close()) fail(path, fmt::format("could not write temporary file '{}'", temporary));
}

// The XDMF sidecar of the complete file, written by the first process alone
// (a small text file); every process learns of a failure.
void write_sidecar(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid) {
  run_agreed(comm, [&] {
    if (comm.rank() == 0) io::write_xdmf_sidecar(path, grid);
  });
}

}  // namespace

void write_file_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, std::uint64_t reserved_bytes,
                      const std::function<void(const io::Hdf5Node& root)>& fill) {
  const bool first = comm.rank() == 0;
  std::unique_ptr<io::OutputTemporary> output;
  std::string temporary;
  run_agreed(comm, [&] {
    if (!first) return;
    output = std::make_unique<io::OutputTemporary>(path);
    temporary = output->temporary().string();
  });
  broadcast(comm, temporary);
  std::optional<io::detail::File> file;
  run_agreed(comm, [&] { file.emplace(create_collectively(comm, path, temporary)); });
  // The file's space before any field is written: a full disk or a file-size
  // limit is then met here, where every process learns of it, and not by
  // one process alone inside a collective write, which would leave the
  // others waiting.
  run_agreed(comm, [&] {
    if (first) io::reserve_output_space(path, temporary, reserved_bytes);
  });
  run_agreed(comm, [&] { write_into(*file, path, temporary, fill); });
  // Every process has closed the file: only now is it complete.
  run_agreed(comm, [&] {
    if (first) output->commit();
  });
}

void write_result_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                        const SlabLayout& layout, std::span<const double> heights, const solvers::SolveResult& result,
                        const io::ResultMetadata& metadata) {
  write_file_slabs(comm, path, io::result_file_bound(grid, result, metadata), [&](const io::Hdf5Node& root) {
    io::write_result_contents(root, grid, heights, result, metadata, {layout.first_row, comm.rank() == 0});
  });
  write_sidecar(comm, path, grid);
}

void write_friction_history_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                                  const SlabLayout& layout, std::span<const double> heights,
                                  const solvers::SolveResult& normal, std::span<const TangentialResult> steps,
                                  std::span<const TangentialLoading> loads, const io::ResultMetadata& metadata) {
  if (steps.empty() || loads.size() != steps.size()) {
    throw InputError(fmt::format("write_friction_history_slabs: {} loads for {} steps", loads.size(), steps.size()));
  }
  const std::string csv = io::friction_history_csv(steps);
  const std::filesystem::path csv_path = io::history_csv_path(path);
  // A previous history's table would not match the new file: removed first,
  // so that an interrupted write leaves no mismatched pair.
  run_agreed(comm, [&] {
    std::error_code ignored;
    if (comm.rank() == 0) std::filesystem::remove(csv_path, ignored);
  });
  // The file holds the step fields and the normal ones: about 7 fields per
  // step beside the single result's, and a coupled step's own normal
  // fields (a single result's without the height and friction fields).
  io::ResultMetadata root_metadata = metadata;
  root_metadata.tangential = &steps.back();
  std::uint64_t bound = io::result_file_bound(grid, normal, root_metadata) +
                        steps.size() * (io::kHdf5SmallItemsBound +
                                        7 * io::hdf5_dataset_bound(io::field_shape(grid), io::Compression::deflate));
  for (const solvers::SolveResult* step : metadata.step_normals) bound += io::result_file_bound(grid, *step, {});
  write_file_slabs(comm, path, bound, [&](const io::Hdf5Node& root) {
    io::write_friction_history_contents(root, grid, heights, normal, steps, loads, metadata, csv,
                                        {layout.first_row, comm.rank() == 0});
  });
  run_agreed(comm, [&] {
    if (comm.rank() == 0) io::write_output_file(csv_path, csv);
  });
  write_sidecar(comm, path, grid);
}

void write_height_map_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                            const SlabLayout& layout, std::span<const double> heights,
                            const io::HeightMapMetadata& metadata) {
  const std::uint64_t bound =
      io::kHdf5SmallItemsBound + io::hdf5_dataset_bound(io::field_shape(grid), io::Compression::deflate);
  write_file_slabs(comm, path, bound, [&](const io::Hdf5Node& root) {
    io::write_height_map_contents(root, grid, layout.first_row, heights, metadata);
  });
  write_sidecar(comm, path, grid);
}

void write_sweep_slabs(const MpiCommunicator& comm, const std::filesystem::path& path, const Grid& grid,
                       const SlabLayout& layout, std::span<const double> heights,
                       std::span<const analysis::SweepStep> steps, const io::ResultMetadata& metadata) {
  if (steps.empty()) throw InputError("write_sweep_slabs: the sweep has no steps");
  write_file_slabs(comm, path, io::sweep_file_bound(grid, steps), [&](const io::Hdf5Node& root) {
    io::write_sweep_contents(root, grid, heights, steps, metadata, {layout.first_row, comm.rank() == 0});
  });
  write_sidecar(comm, path, grid);
}

}  // namespace halfspace::mpi
