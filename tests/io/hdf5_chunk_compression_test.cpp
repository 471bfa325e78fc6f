// The threaded chunk compression of Hdf5Node::write_dataset
// (src/io/hdf5_chunk_compression.cpp) against HDF5's own filter pipeline:
// the same datasets written both ways must store the same bytes in every
// chunk (shuffle + deflate, edges padded), with no filter skipped, and read
// back bit for bit.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/threads.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

using test::H5;

// The chunk shape write_dataset gives `dims` (docs/file-format.md: whole
// rows, at most 65536 elements, balanced pieces).
std::vector<hsize_t> stored_chunk(hid_t file, const std::string& name) {
  const H5 dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + name);
  const H5 plist(H5Dget_create_plist(dataset.get()), H5Pclose, "creation properties of " + name);
  std::vector<hsize_t> chunk(8);
  const int rank = H5Pget_chunk(plist.get(), 8, chunk.data());
  chunk.resize(rank > 0 ? static_cast<std::size_t>(rank) : 0);
  return chunk;
}

// `data` written by HDF5's pipeline into `file` with `chunk`, shuffle and
// deflate at level 4, as the library declares its datasets.
void write_by_pipeline(hid_t file, const std::string& name, const std::vector<hsize_t>& dims,
                       const std::vector<hsize_t>& chunk, hid_t type, const void* data) {
  const H5 space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, "space");
  const H5 plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "plist");
  test::check(H5Pset_chunk(plist.get(), static_cast<int>(chunk.size()), chunk.data()), "chunk");
  test::check(H5Pset_shuffle(plist.get()), "shuffle");
  test::check(H5Pset_deflate(plist.get(), 4), "deflate");
  const H5 dataset(H5Dcreate2(file, name.c_str(), type, space.get(), H5P_DEFAULT, plist.get(), H5P_DEFAULT), H5Dclose,
                   "create " + name);
  test::check(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
}

// Every chunk of `name` in both files: the same stored bytes and filter mask 0.
void expect_same_chunks(hid_t ours, hid_t theirs, const std::string& name) {
  const H5 a(H5Dopen2(ours, name.c_str(), H5P_DEFAULT), H5Dclose, "open ours " + name);
  const H5 b(H5Dopen2(theirs, name.c_str(), H5P_DEFAULT), H5Dclose, "open theirs " + name);
  const H5 space(H5Dget_space(a.get()), H5Sclose, "space");
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space.get())));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  const std::vector<hsize_t> chunk = stored_chunk(ours, name);
  ASSERT_EQ(chunk.size(), dims.size()) << name << " is chunked";
  std::vector<hsize_t> at(dims.size(), 0);
  std::size_t chunks = 0;
  while (true) {
    hsize_t size_a = 0, size_b = 0;
    ASSERT_GE(H5Dget_chunk_storage_size(a.get(), at.data(), &size_a), 0);
    ASSERT_GE(H5Dget_chunk_storage_size(b.get(), at.data(), &size_b), 0);
    std::vector<unsigned char> bytes_a(size_a), bytes_b(size_b);
    std::uint32_t mask_a = 1, mask_b = 1;
    ASSERT_GE(H5Dread_chunk(a.get(), H5P_DEFAULT, at.data(), &mask_a, bytes_a.data()), 0);
    ASSERT_GE(H5Dread_chunk(b.get(), H5P_DEFAULT, at.data(), &mask_b, bytes_b.data()), 0);
    EXPECT_EQ(mask_a, 0U) << name;
    EXPECT_EQ(mask_a, mask_b) << name;
    EXPECT_EQ(bytes_a, bytes_b) << name << ": chunk " << chunks;
    ++chunks;
    std::size_t axis = dims.size();
    while (axis > 0) {
      --axis;
      at[axis] += chunk[axis];
      if (at[axis] < dims[axis]) break;
      at[axis] = 0;
      if (axis == 0) return;
    }
  }
}

struct Case {
  std::string name;
  std::vector<std::size_t> shape;
};

class Hdf5ChunkCompressionTest : public ::testing::TestWithParam<int> {};

TEST_P(Hdf5ChunkCompressionTest, StoresWhatHdf5sPipelineStores) {
  const int saved = threads();
  set_threads(GetParam());
  const test::TempDir dir;
  // Partial last chunks along rows (301 rows in chunks of 151), along a
  // wide row (70001 in chunks of 35001), in 1D, and a smooth field that
  // deflate shrinks beside a noisy one it barely does.
  const std::vector<Case> cases = {
      {"rows", {301, 250}}, {"wide", {3, 70001}}, {"line", {100001}}, {"noise", {256, 300}}};
  std::vector<std::vector<double>> values;
  for (const Case& c : cases) {
    std::size_t n = 1;
    for (const std::size_t d : c.shape) n *= d;
    std::vector<double> v(n);
    std::uint64_t state = 12345;
    for (std::size_t k = 0; k < n; ++k) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      const double noise = static_cast<double>(state >> 11) * 0x1.0p-53;
      v[k] = c.name == "noise" ? noise : std::sin(1e-3 * static_cast<double>(k)) * (k % 7 == 0 ? 0.0 : 1.0);
    }
    values.push_back(std::move(v));
  }
  std::vector<std::uint8_t> flags(301 * 257);
  for (std::size_t k = 0; k < flags.size(); ++k) flags[k] = (k / 13) % 3 == 0 ? 1 : 0;

  write_hdf5_file(dir / "ours.h5", [&](const Hdf5Node& root) {
    for (std::size_t c = 0; c < cases.size(); ++c) root.write_dataset(cases[c].name, cases[c].shape, values[c], "m");
    root.write_dataset("flags", {301, 257}, std::span<const std::uint8_t>(flags), "");
  });
  {
    const auto theirs = test::create_file(dir / "theirs.h5");
    const auto ours = test::open_file(dir / "ours.h5");
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const std::vector<hsize_t> dims(cases[c].shape.begin(), cases[c].shape.end());
      write_by_pipeline(theirs.get(), cases[c].name, dims, stored_chunk(ours.get(), cases[c].name), H5T_IEEE_F64LE,
                        values[c].data());
    }
    write_by_pipeline(theirs.get(), "flags", {301, 257}, stored_chunk(ours.get(), "flags"), H5T_STD_U8LE, flags.data());
  }
  const auto ours = test::open_file(dir / "ours.h5");
  const auto theirs = test::open_file(dir / "theirs.h5");
  EXPECT_EQ(stored_chunk(ours.get(), "rows"), (std::vector<hsize_t>{151, 250}));
  EXPECT_EQ(stored_chunk(ours.get(), "wide"), (std::vector<hsize_t>{1, 35001}));
  for (std::size_t c = 0; c < cases.size(); ++c) {
    expect_same_chunks(ours.get(), theirs.get(), cases[c].name);
    EXPECT_EQ(test::read_dataset<double>(ours.get(), "/" + cases[c].name, H5T_NATIVE_DOUBLE), values[c])
        << cases[c].name;
  }
  expect_same_chunks(ours.get(), theirs.get(), "flags");
  EXPECT_EQ(test::read_dataset<std::uint8_t>(ours.get(), "/flags", H5T_NATIVE_UINT8), flags);
  set_threads(saved);
}

INSTANTIATE_TEST_SUITE_P(Threads, Hdf5ChunkCompressionTest, ::testing::Values(1, 3));

}  // namespace
}  // namespace halfspace::io
