// A check of an HDF5 file's superblock before HDF5 opens it. HDF5 1.10 trusts
// fields of the superblock that the format reserves: a 50-byte file whose
// reserved byte is 0xf9 made H5Fopen allocate 4 GiB and spend 12 s before it
// failed (found by fuzz/hdf5_fuzzer.cpp). The fixed fields are checked here
// against the format specification (HDF5 File Format Specification 3.0,
// "Level 0A: Format Signature and Superblock"); the rest is HDF5's to judge.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace halfspace::io::detail {

// What is wrong with the superblock of the HDF5 file at `path`, or nothing
// if its fixed fields are as the format allows (or no signature is found:
// HDF5 says so in its own words). Throws nothing; an unreadable file is
// left to HDF5 as well.
std::optional<std::string> hdf5_superblock_problem(const std::filesystem::path& path);

}  // namespace halfspace::io::detail
