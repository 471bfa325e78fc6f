// The conventions of every HDF5 file halfspace writes (docs/file-format.md),
// in one place for all writers (results, sweeps, height maps, the paper's
// tables): numbers as scalar float64 or int64 little-endian attributes;
// strings as variable-length UTF-8 (invalid bytes and NULs replaced by
// U+FFFD); datasets with a `units` attribute, contiguous up to 65536 elements
// and above that chunked in whole rows with shuffle and deflate (or, asked
// for, without filters); the file
// assembled in memory and written atomically through write_output_file (or,
// too large for memory, written in place under its temporary name).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "halfspace/grid.hpp"

namespace halfspace::io {

// How a chunked float64 dataset is stored: shuffle and deflate (the
// convention), or without filters, for large fields that compress little
// (the stress volume: docs/performance.md#subsurface-stresses).
enum class Compression { deflate, none };

// A group or dataset of a file that write_hdf5_file is building; valid only
// inside its fill callback. Every method throws FileError with the reason
// (write_hdf5_file adds the path).
class Hdf5Node {
 public:
  Hdf5Node(Hdf5Node&& other) noexcept;
  Hdf5Node& operator=(Hdf5Node&& other) noexcept;
  Hdf5Node(const Hdf5Node&) = delete;
  Hdf5Node& operator=(const Hdf5Node&) = delete;
  ~Hdf5Node();

  void write_double_attribute(std::string_view name, double value) const;
  void write_int64_attribute(std::string_view name, std::int64_t value) const;
  void write_string_attribute(std::string_view name, std::string_view value) const;

  // A dataset of `shape` (row-major; a zero extent gives an empty dataset)
  // holding `values` (as many as the shape's product), with a `units`
  // string attribute unless `units` is empty. Returns the dataset, for more
  // attributes.
  Hdf5Node write_dataset(std::string_view name, const std::vector<std::size_t>& shape, std::span<const double> values,
                         std::string_view units, Compression compression = Compression::deflate) const;
  Hdf5Node write_dataset(std::string_view name, const std::vector<std::size_t>& shape,
                         std::span<const std::int64_t> values, std::string_view units) const;
  Hdf5Node write_dataset(std::string_view name, const std::vector<std::size_t>& shape,
                         std::span<const std::uint8_t> values, std::string_view units) const;

  // A dataset of `shape` of which this process writes the rows (indices
  // along the first axis) first_row .. first_row + r - 1, `values` holding
  // them (r times the product of the other extents; r may be 0), and other
  // processes the rest: stored as write_dataset stores it. In a file several
  // processes write (fill_hdf5_file), every process calls it, with the same
  // name, shape and units. The same as write_dataset for all rows.
  Hdf5Node write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape, std::size_t first_row,
                              std::span<const double> values, std::string_view units) const;
  Hdf5Node write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape, std::size_t first_row,
                              std::span<const std::uint8_t> values, std::string_view units) const;
  Hdf5Node write_dataset_rows(std::string_view name, const std::vector<std::size_t>& shape, std::size_t first_row,
                              std::span<const std::int64_t> values, std::string_view units) const;

  // A float64 dataset of `shape` (rank >= 2, stored as write_dataset would)
  // whose values come later, slab by slab along the first axis, through
  // write_slabs on the returned node: for fields too large to hold at once.
  Hdf5Node create_dataset(std::string_view name, const std::vector<std::size_t>& shape, std::string_view units,
                          Compression compression = Compression::deflate) const;
  // On a dataset made by create_dataset: writes `values`, whole slabs of the
  // first axis, starting at slab `first`.
  void write_slabs(std::size_t first, std::span<const double> values) const;
  // The same for part of one slab: its rows (indices along the second axis)
  // first_row .. first_row + r - 1, `values` holding them (r times the
  // product of the remaining extents; r may be 0): in a file several
  // processes write, each its rows, every process calling it alike.
  void write_slab_rows(std::size_t slab, std::size_t first_row, std::span<const double> values) const;

  Hdf5Node create_group(std::string_view name) const;

 private:
  friend void write_hdf5_file(const std::filesystem::path&, const std::function<void(const Hdf5Node&)>&);
  friend std::vector<char> hdf5_file_image(const std::filesystem::path&, const std::function<void(const Hdf5Node&)>&);
  friend void fill_hdf5_file(std::int64_t, std::int64_t, const std::function<void(const Hdf5Node&)>&);
  // An HDF5 object id (hid_t), owned, and the transfer property list its
  // datasets are written with (H5P_DEFAULT, 0, or a collective one; not owned).
  explicit Hdf5Node(std::int64_t id, std::int64_t transfer = 0) : id_(id), transfer_(transfer) {}
  std::int64_t id_ = -1;
  std::int64_t transfer_ = 0;
};

// Builds the file in memory by calling fill(root) and writes it to `path`
// with write_output_file (checked path, temporary name, fsync, rename).
// Throws FileError "cannot write output '<path>': <reason>"; no partial file
// is left behind.
//
// Why in memory: HDF5 1.10 cannot recover from an I/O error (a full disk)
// while closing a file on disk; in memory it never meets one, and ours are
// reported like any other. The cost is about twice the file's size in
// memory while writing.
void write_hdf5_file(const std::filesystem::path& path, const std::function<void(const Hdf5Node& root)>& fill);

// Fills a file the caller has created (with its own file access: the
// parallel HDF5 of an MPI run) and will close: calls fill(root), whose
// datasets are written with the transfer property list `transfer` (a
// collective one when processes write their rows of each field). Throws
// FileError with the reason; the caller removes the file.
void fill_hdf5_file(std::int64_t file, std::int64_t transfer, const std::function<void(const Hdf5Node& root)>& fill);

// The same for a file too large to hold in memory (the stress volume): HDF5
// writes the temporary file on disk directly (OutputTemporary), after
// `reserved_bytes`, an upper bound on the file's size, has been reserved on
// disk, so that a full disk is met before HDF5 writes (the case that HDF5
// 1.10 does not survive) and reported like any other error. Memory: HDF5's
// caches (a few MiB) beside what `fill` holds.
void write_large_hdf5_file(const std::filesystem::path& path, std::uint64_t reserved_bytes,
                           const std::function<void(const Hdf5Node& root)>& fill);

// Upper bounds for write_large_hdf5_file's reservation: the bytes a float64
// dataset of `shape` takes in the file, stored as write_dataset stores it
// (values, deflate's worst case, chunk index, object header with a few
// attributes), and those of a file's small items (superblock, groups,
// attributes, small datasets).
std::uint64_t hdf5_dataset_bound(const std::vector<std::size_t>& shape, Compression compression);
inline constexpr std::uint64_t kHdf5SmallItemsBound = std::uint64_t{1} << 20;

// The shape of a field dataset on `grid`: (nx) in 1D, (ny, nx) in 2D.
std::vector<std::size_t> field_shape(const Grid& grid);

}  // namespace halfspace::io
