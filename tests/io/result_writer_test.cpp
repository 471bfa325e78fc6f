// Tests of write_result: 1D and 2D results read back with the HDF5 C API
// (shapes, bit-exact fields, storage layout, every attribute), the atomic
// write and its failure modes, and string handling.
#include "halfspace/io/result_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/hdf5_height_map_reader.hpp"
#include "halfspace/version.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// The writer's compression threshold and chunk target, from
// docs/file-format.md: fields with more elements are chunked.
constexpr std::size_t kChunkThreshold = 65536;

// A result whose fields are distinct, non-trivial doubles (so a swapped or
// transposed field shows), with zero and positive pressures.
SolveResult make_result(const Grid& grid, std::size_t history_length) {
  const auto n = static_cast<Eigen::Index>(grid.size());
  SolveResult result;
  result.status = SolveStatus::iteration_limit;
  result.message = "stopped after 17 iterations: residual 3e-7 > tolerance 1e-8";
  result.solver = "polonsky-keer";
  result.iterations = 17;
  result.residual = 3.0000000000000004e-7;
  result.tolerance = 1e-8;
  for (std::size_t k = 0; k < history_length; ++k) result.residual_history.push_back(std::pow(0.5, double(k)) / 3.0);
  result.operator_applications = 35;
  result.preconditioner_applications = 17;
  result.coarse = {3, 41, 12.5, 6.25};
  result.approach = 1.234e-7;
  result.total_force = 0.1 / 3.0;
  result.mean_pressure = 1.7e6 / 7.0;
  result.max_pressure = 9.9e8 / 11.0;
  result.contact_fraction = 0.0625;
  result.wall_seconds = 0.125;
  result.pressure.resize(n);
  result.displacement.resize(n);
  result.gap.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double x = static_cast<double>(k);
    result.pressure[k] = std::max(0.0, std::sin(0.013 * x)) * 1e8 / 3.0;
    result.displacement[k] = std::cos(0.007 * x) * 1e-7;
    result.gap[k] = result.pressure[k] > 0.0 ? 0.0 : std::exp(-1e-3 * x) * 1e-8;
  }
  return result;
}

std::vector<double> make_height(const Grid& grid) {
  std::vector<double> height(grid.size());
  for (std::size_t k = 0; k < height.size(); ++k) height[k] = std::sin(0.1 * static_cast<double>(k)) * 1e-6 / 7.0;
  return height;
}

ResultMetadata make_metadata() {
  ResultMetadata metadata;
  metadata.e_star = 1.1e11;
  metadata.load_mode = "force";
  metadata.threads = 3;
  metadata.command_line = "halfspace solve --config run.toml";
  metadata.config = "[load]\nmode = \"force\"\nvalue = 0.0333\n";
  metadata.height_source = "surface.h5:/height";
  return metadata;
}

std::vector<double> as_vector(const Eigen::ArrayXd& a) {
  return std::vector<double>(a.data(), a.data() + a.size());
}

// Fields, shapes and storage of a written file against what was written.
void expect_fields(hid_t file, const Grid& grid, const std::vector<double>& height, const SolveResult& result) {
  const std::vector<hsize_t> shape =
      grid.dimension() == 1 ? std::vector<hsize_t>{grid.nx()} : std::vector<hsize_t>{grid.ny(), grid.nx()};
  const std::vector<std::pair<std::string, std::vector<double>>> fields{
      {"/height", height},
      {"/pressure", as_vector(result.pressure)},
      {"/gap", as_vector(result.gap)},
      {"/displacement", as_vector(result.displacement)}};
  for (const auto& [name, expected] : fields) {
    SCOPED_TRACE(name);
    EXPECT_EQ(test::dataset_shape(file, name), shape);
    const test::StoredType type = test::dataset_type(file, name);
    EXPECT_EQ(type.type_class, H5T_FLOAT);
    EXPECT_EQ(type.size, 8u);
    EXPECT_EQ(type.order, H5T_ORDER_LE);
    // Bit-exact: EXPECT_EQ on doubles compares with ==, no tolerance.
    EXPECT_EQ(test::read_dataset<double>(file, name, H5T_NATIVE_DOUBLE), expected);
  }

  EXPECT_EQ(test::dataset_shape(file, "/contact"), shape);
  const test::StoredType contact_type = test::dataset_type(file, "/contact");
  EXPECT_EQ(contact_type.type_class, H5T_INTEGER);
  EXPECT_EQ(contact_type.size, 1u);
  EXPECT_EQ(contact_type.sign, H5T_SGN_NONE);
  const auto contact = test::read_dataset<std::uint8_t>(file, "/contact", H5T_NATIVE_UINT8);
  ASSERT_EQ(contact.size(), grid.size());
  std::size_t in_contact = 0;
  for (std::size_t k = 0; k < contact.size(); ++k) {
    const bool pressed = result.pressure[static_cast<Eigen::Index>(k)] > 0.0;
    ASSERT_EQ(contact[k], pressed ? 1 : 0) << "at flat index " << k;
    in_contact += pressed ? 1 : 0;
  }
  EXPECT_GT(in_contact, 0u);  // the mask is not trivially all zero or all one
  EXPECT_LT(in_contact, grid.size());

  EXPECT_EQ(test::dataset_shape(file, "/residual_history"), std::vector<hsize_t>{result.residual_history.size()});
  EXPECT_EQ(test::read_dataset<double>(file, "/residual_history", H5T_NATIVE_DOUBLE), result.residual_history);

  const test::H5 root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose, "root");
  for (const char* name : {"/height", "/gap", "/displacement"}) {
    const test::H5 dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, name);
    EXPECT_EQ(test::read_string_attribute(dataset.get(), "units"), "m") << name;
  }
  const test::H5 pressure(H5Dopen2(file, "/pressure", H5P_DEFAULT), H5Dclose, "pressure");
  EXPECT_EQ(test::read_string_attribute(pressure.get(), "units"), "Pa");
}

// Every root attribute, with its stored type: float64, int64 or
// variable-length UTF-8 string.
void expect_attributes(hid_t file, const Grid& grid, const SolveResult& result, const ResultMetadata& metadata) {
  const auto expect_double = [&](const char* name, double expected) {
    const test::StoredType type = test::attribute_type(file, name);
    EXPECT_TRUE(type.type_class == H5T_FLOAT && type.size == 8) << name;
    EXPECT_EQ(test::read_double_attribute(file, name), expected) << name;
  };
  const auto expect_int = [&](const char* name, std::int64_t expected) {
    const test::StoredType type = test::attribute_type(file, name);
    EXPECT_TRUE(type.type_class == H5T_INTEGER && type.size == 8 && type.sign == H5T_SGN_2) << name;
    EXPECT_EQ(test::read_int64_attribute(file, name), expected) << name;
  };
  const auto expect_string = [&](const char* name, const std::string& expected) {
    EXPECT_EQ(test::read_string_attribute(file, name), expected) << name;
  };

  expect_string("format", "halfspace-result");
  expect_int("format_version", 1);
  expect_int("dimension", grid.dimension());
  expect_int("nx", static_cast<std::int64_t>(grid.nx()));
  expect_int("ny", static_cast<std::int64_t>(grid.ny()));
  expect_double("dx", grid.dx());
  expect_double("dy", grid.dimension() == 1 ? 0.0 : grid.dy());
  expect_string("boundary", std::string(to_string(grid.boundary())));
  expect_double("E_star", metadata.e_star);
  expect_string("load_mode", metadata.load_mode);
  expect_double("total_force", result.total_force);
  expect_double("mean_pressure", result.mean_pressure);
  expect_double("approach", result.approach);
  expect_double("contact_fraction", result.contact_fraction);
  expect_double("max_pressure", result.max_pressure);
  expect_int("iterations", result.iterations);
  expect_int("operator_applications", result.operator_applications);
  expect_int("preconditioner_applications", result.preconditioner_applications);
  expect_int("coarse_levels", result.coarse.levels);
  expect_int("coarse_iterations", result.coarse.iterations);
  expect_double("coarse_operator_work", result.coarse.operator_work);
  expect_double("coarse_preconditioner_work", result.coarse.preconditioner_work);
  expect_int("deflation_block", static_cast<std::int64_t>(result.deflation.block));
  expect_int("deflated_iterations", result.deflation.deflated_iterations);
  expect_int("deflation_declined", result.deflation.declined);
  expect_double("residual", result.residual);
  expect_double("tolerance", result.tolerance);
  expect_int("converged", result.converged() ? 1 : 0);
  expect_string("status", std::string(to_string(result.status)));
  expect_string("message", result.message);
  expect_string("solver", result.solver);
  expect_double("solve_seconds", result.wall_seconds);
  expect_int("threads", metadata.threads);
  expect_string("halfspace_version", fmt::format("{} ({})", kVersion, kGitHash));
  expect_string("command_line", metadata.command_line);
  expect_string("config", metadata.config);
  expect_string("height_source", metadata.height_source);
  EXPECT_NE(test::read_string_attribute(file, "units").find("N/m in 1D"), std::string::npos);
}

struct Storage {
  H5D_layout_t layout;
  int filter_count;
  std::vector<hsize_t> chunk;  // empty unless chunked
};

Storage storage_of(hid_t file, const char* name) {
  const test::H5 dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, name);
  const test::H5 properties(H5Dget_create_plist(dataset.get()), H5Pclose, "creation properties");
  Storage storage{H5Pget_layout(properties.get()), H5Pget_nfilters(properties.get()), {}};
  if (storage.layout == H5D_CHUNKED) {
    storage.chunk.resize(2);
    storage.chunk.resize(static_cast<std::size_t>(H5Pget_chunk(properties.get(), 2, storage.chunk.data())));
  }
  return storage;
}

TEST(ResultWriterTest, RoundTripsFieldsAndAttributes1D) {
  const TempDir dir;
  const Grid grid = Grid::line(1000, 2.5e-7, Boundary::free);
  const std::vector<double> height = make_height(grid);
  const SolveResult result = make_result(grid, 5);
  const ResultMetadata metadata = make_metadata();
  const fs::path path = dir / "profile.h5";
  write_result(path, grid, height, result, metadata);

  const auto file = test::open_file(path);
  expect_fields(file.get(), grid, height, result);
  expect_attributes(file.get(), grid, result, metadata);
  const Storage storage = storage_of(file.get(), "/pressure");
  EXPECT_EQ(storage.layout, H5D_CONTIGUOUS);  // small fields stay contiguous
  EXPECT_EQ(storage.filter_count, 0);
}

TEST(ResultWriterTest, RoundTripsFieldsAndAttributes2DChunked) {
  const TempDir dir;
  // nx != ny and dx != dy catch a transposed shape or swapped spacing; the
  // size exceeds the chunking threshold.
  const Grid grid = Grid::plane(300, 257, 1e-6, 2e-6, Boundary::periodic);
  ASSERT_GT(grid.size(), kChunkThreshold);
  const std::vector<double> height = make_height(grid);
  SolveResult result = make_result(grid, 40);
  result.status = SolveStatus::converged;
  result.message.clear();
  const ResultMetadata metadata = make_metadata();
  const fs::path path = dir / "map.h5";
  write_result(path, grid, height, result, metadata);

  const auto file = test::open_file(path);
  expect_fields(file.get(), grid, height, result);
  expect_attributes(file.get(), grid, result, metadata);
  for (const char* name : {"/height", "/pressure", "/gap", "/displacement", "/contact"}) {
    const Storage storage = storage_of(file.get(), name);
    EXPECT_EQ(storage.layout, H5D_CHUNKED) << name;
    EXPECT_EQ(storage.filter_count, 2) << name << ": shuffle and deflate";
    // Whole rows, at most kChunkThreshold elements, 257 rows in two equal chunks.
    EXPECT_EQ(storage.chunk, (std::vector<hsize_t>{129, 300})) << name;
  }
}

TEST(ResultWriterTest, ChunksLargeProfileInEqualPieces) {
  const TempDir dir;
  const Grid grid = Grid::line(70000, 1e-8, Boundary::free);
  const std::vector<double> height = make_height(grid);
  const SolveResult result = make_result(grid, 2);
  const fs::path path = dir / "long-profile.h5";
  write_result(path, grid, height, result, make_metadata());

  const auto file = test::open_file(path);
  expect_fields(file.get(), grid, height, result);
  const Storage storage = storage_of(file.get(), "/gap");
  EXPECT_EQ(storage.layout, H5D_CHUNKED);
  EXPECT_EQ(storage.chunk, std::vector<hsize_t>{35000});
}

// Above kInMemoryResultBytes the file is written in place rather than
// assembled in memory: the same fields, attributes and layout, and no
// temporary left beside it.
TEST(ResultWriterTest, WritesAResultAboveTheInMemoryLimitInPlace) {
  const TempDir dir;
  const Grid grid = Grid::plane(1300, 1200, 1e-6, 1e-6, Boundary::periodic);
  const SolveResult result = make_result(grid, 3);
  const ResultMetadata metadata = make_metadata();
  ASSERT_GT(result_file_bound(grid, result, metadata), kInMemoryResultBytes);
  const std::vector<double> height = make_height(grid);
  write_result(dir / "large.h5", grid, height, result, metadata);

  const auto file = test::open_file(dir / "large.h5");
  expect_fields(file.get(), grid, height, result);
  expect_attributes(file.get(), grid, result, metadata);
  EXPECT_EQ(storage_of(file.get(), "/pressure").filter_count, 2) << "shuffle and deflate";
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"large.h5", "large.xdmf"}));
}

TEST(ResultWriterTest, WritesEmptyResidualHistoryAsZeroLengthDataset) {
  const TempDir dir;
  const Grid grid = Grid::line(8, 1e-6, Boundary::periodic);
  const SolveResult result = make_result(grid, 0);
  const fs::path path = dir / "empty-history.h5";
  write_result(path, grid, make_height(grid), result, make_metadata());

  const auto file = test::open_file(path);
  EXPECT_EQ(test::dataset_shape(file.get(), "/residual_history"), std::vector<hsize_t>{0});
  EXPECT_EQ(test::read_string_attribute(file.get(), "message"), result.message);
}

TEST(ResultWriterTest, LeavesNoTemporaryFileAfterSuccess) {
  const TempDir dir;
  const Grid grid = Grid::plane(4, 3, 1e-6, 1e-6, Boundary::free);
  write_result(dir / "out.h5", grid, make_height(grid), make_result(grid, 2), make_metadata());
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.h5", "out.xdmf"}));
}

TEST(ResultWriterTest, ReplacesAnExistingFile) {
  const TempDir dir;
  const fs::path path = dir / "out.h5";
  std::ofstream(path) << "an old result";
  const Grid grid = Grid::line(16, 1e-6, Boundary::free);
  const SolveResult result = make_result(grid, 3);
  write_result(path, grid, make_height(grid), result, make_metadata());

  const auto file = test::open_file(path);
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE), as_vector(result.pressure));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.h5", "out.xdmf"}));
}

TEST(ResultWriterTest, ThrowsForMissingDirectoryAndLeavesNothing) {
  const TempDir dir;
  const fs::path missing = dir / "nonexistent";
  const fs::path path = missing / "x.h5";
  const Grid grid = Grid::line(8, 1e-6, Boundary::free);
  try {
    write_result(path, grid, make_height(grid), make_result(grid, 1), make_metadata());
    FAIL() << "no FileError for " << path;
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'" + path.string() + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("directory '" + missing.string() + "' does not exist"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ResultWriterTest, ThrowsWhenParentIsAFile) {
  const TempDir dir;
  std::ofstream(dir / "plain") << "not a directory";
  const fs::path path = dir / "plain" / "x.h5";
  const Grid grid = Grid::line(8, 1e-6, Boundary::free);
  try {
    write_result(path, grid, make_height(grid), make_result(grid, 1), make_metadata());
    FAIL() << "no FileError for " << path;
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("is not a directory"), std::string::npos) << error.what();
  }
}

// An existing file under the temporary name may belong to another writer:
// it is neither followed nor removed.
TEST(ResultWriterTest, RefusesExistingTemporaryFile) {
  const TempDir dir;
  const fs::path path = dir / "out.h5";
  const fs::path temporary = dir / fmt::format("out.h5.tmp-{}", ::getpid());
  std::ofstream(temporary) << "someone else's";
  const Grid grid = Grid::line(8, 1e-6, Boundary::free);
  try {
    write_result(path, grid, make_height(grid), make_result(grid, 1), make_metadata());
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("already exists"), std::string::npos) << error.what();
  }
  std::string kept;
  std::getline(std::ifstream(temporary), kept);
  EXPECT_EQ(kept, "someone else's");
  EXPECT_FALSE(fs::exists(path));
}

TEST(ResultWriterTest, ThrowsForReadOnlyDirectory) {
  const Grid grid = Grid::line(8, 1e-6, Boundary::free);
  if (::geteuid() == 0) {
    // Root may write to any ordinary directory, but nobody may create files in /proc.
    const fs::path path = "/proc/halfspace-result-test.h5";
    try {
      write_result(path, grid, make_height(grid), make_result(grid, 1), make_metadata());
      ADD_FAILURE() << "no FileError";
    } catch (const FileError& error) {
      EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
    }
    EXPECT_FALSE(fs::exists(path));
    return;
  }
  const TempDir dir;
  const fs::path locked = dir / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  try {
    write_result(locked / "x.h5", grid, make_height(grid), make_result(grid, 1), make_metadata());
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("is not writable"), std::string::npos) << error.what();
  }
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_TRUE(fs::is_empty(locked));
}

// Renaming a file onto a non-empty directory fails after the temporary file
// has been written in full: the path that must clean up.
TEST(ResultWriterTest, RemovesTemporaryFileWhenRenameFails) {
  const TempDir dir;
  const fs::path path = dir / "taken";
  fs::create_directory(path);
  std::ofstream(path / "keep") << "occupied";
  const Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free);
  try {
    write_result(path, grid, make_height(grid), make_result(grid, 1), make_metadata());
    FAIL() << "no FileError for " << path;
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'" + path.string() + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("rename"), std::string::npos) << message;
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken"});
  EXPECT_TRUE(fs::exists(path / "keep"));
}

// A failure while the temporary file is being written (here the file-size
// limit, which behaves like a full disk) removes it and names the reason.
TEST(ResultWriterTest, RemovesTemporaryFileWhenTheDiskWriteFails) {
  constexpr rlim_t kSizeLimit = 4096;  // far below the ~70 KB of this result
  const TempDir dir;
  const Grid grid = Grid::plane(64, 32, 1e-6, 1e-6, Boundary::free);
  const fs::path path = dir / "out.h5";
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  if (saved.rlim_max != RLIM_INFINITY && saved.rlim_max < kSizeLimit) GTEST_SKIP() << "file size limit already low";
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG instead of being killed
  rlimit limited = saved;
  limited.rlim_cur = kSizeLimit;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &limited), 0);
  std::string message;
  try {
    write_result(path, grid, make_height(grid), make_result(grid, 3), make_metadata());
  } catch (const FileError& error) {
    message = error.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);

  EXPECT_NE(message.find("cannot write output '" + path.string() + "'"), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

// What stands at the output path must be a regular file: a FIFO (like a
// device node, which root's rename would replace by a regular file) is
// refused before anything is written, and stays.
TEST(ResultWriterTest, RefusesAFifoAtTheOutputPathAndLeavesIt) {
  const TempDir dir;
  const fs::path pipe = dir / "out.h5";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  const Grid grid = Grid::line(8, 1e-6, Boundary::free);
  try {
    write_result(pipe, grid, make_height(grid), make_result(grid, 1), make_metadata());
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cannot write output '" + pipe.string() + "': it is a FIFO"), std::string::npos) << message;
  }
  EXPECT_EQ(fs::symlink_status(pipe).type(), fs::file_type::fifo);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.h5"});
}

// A symbolic link at the output path is followed: the result replaces the
// file it names, and the link stays.
TEST(ResultWriterTest, WritesThroughASymbolicLink) {
  const TempDir dir;
  std::ofstream(dir / "target.h5") << "an old result";
  fs::create_symlink("target.h5", dir / "latest.h5");
  const Grid grid = Grid::line(16, 1e-6, Boundary::free);
  const SolveResult result = make_result(grid, 3);
  write_result(dir / "latest.h5", grid, make_height(grid), result, make_metadata());
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "latest.h5")));
  const auto file = test::open_file(dir / "target.h5");
  EXPECT_EQ(test::read_dataset<double>(file.get(), "/pressure", H5T_NATIVE_DOUBLE), as_vector(result.pressure));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"latest.h5", "latest.xdmf", "target.h5"}));
}

TEST(ResultWriterTest, RejectsFieldOfWrongSizeNamingIt) {
  const TempDir dir;
  const Grid grid = Grid::plane(5, 4, 1e-6, 1e-6, Boundary::free);
  SolveResult result = make_result(grid, 1);
  result.gap.resize(19);
  const fs::path path = dir / "out.h5";
  try {
    write_result(path, grid, make_height(grid), result, make_metadata());
    FAIL() << "no InputError";
  } catch (const FileError& error) {
    FAIL() << "a size mismatch is a caller error, not a file error: " << error.what();
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'gap' has 19 values"), std::string::npos) << message;
    EXPECT_NE(message.find("the grid has 20 cells (5x4)"), std::string::npos) << message;
  }
  const std::vector<double> short_height(3, 0.0);
  EXPECT_THROW(write_result(path, grid, short_height, make_result(grid, 1), make_metadata()), InputError);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ResultWriterTest, StoresStringsAsUtf8ReplacingInvalidBytes) {
  const TempDir dir;
  const Grid grid = Grid::line(4, 1e-6, Boundary::free);
  ResultMetadata metadata = make_metadata();
  metadata.command_line = "halfspace solve --surface \xC3\xA9paisseur.h5 --out r\xE9sultat.h5";  // valid, Latin-1
  metadata.config = std::string(100000, 'x');  // beyond the 64 KiB limit of a compact attribute
  metadata.height_source.clear();
  const fs::path path = dir / "strings.h5";
  write_result(path, grid, make_height(grid), make_result(grid, 1), metadata);

  const auto file = test::open_file(path);
  EXPECT_EQ(test::read_string_attribute(file.get(), "command_line"),
            "halfspace solve --surface \xC3\xA9paisseur.h5 --out r\xEF\xBF\xBDsultat.h5");
  EXPECT_EQ(test::read_string_attribute(file.get(), "config"), metadata.config);
  EXPECT_EQ(test::read_string_attribute(file.get(), "height_source"), "");
}

TEST(ResultWriterTest, ResultFileReadsBackAsHeightMap) {
  const TempDir dir;
  const Grid grid = Grid::plane(6, 5, 1e-6, 3e-6, Boundary::free);
  const std::vector<double> height = make_height(grid);
  const fs::path path = dir / "result.h5";
  write_result(path, grid, height, make_result(grid, 1), make_metadata());

  const HeightMap map = read_hdf5_height_map(path);
  EXPECT_EQ(map.nx, 6u);
  EXPECT_EQ(map.ny, 5u);
  EXPECT_EQ(map.dx, 1e-6);
  EXPECT_EQ(map.dy, 3e-6);
  EXPECT_EQ(as_vector(map.heights), height);
}

}  // namespace
}  // namespace halfspace::io
