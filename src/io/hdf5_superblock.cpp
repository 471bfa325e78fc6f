#include "hdf5_superblock.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <fstream>

namespace halfspace::io::detail {
namespace {

constexpr std::array<unsigned char, 8> kSignature = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
constexpr std::uintmax_t kUndefined = ~std::uintmax_t{0};

// A little-endian address or length of `size` bytes; kUndefined for the
// format's undefined address (all bits set) and for values beyond 64 bits.
std::uintmax_t decode(const unsigned char* bytes, unsigned size) {
  bool all_set = true;
  std::uintmax_t value = 0;
  for (unsigned k = 0; k < size; ++k) {
    all_set = all_set && bytes[k] == 0xff;
    if (k >= 8) {
      if (bytes[k] != 0) return kUndefined;
      continue;
    }
    value |= static_cast<std::uintmax_t>(bytes[k]) << (8 * k);
  }
  return all_set ? kUndefined : value;
}

// The bytes read after the signature: the longest fixed part (version 1,
// 32-byte offsets) and more.
constexpr std::size_t kRead = 20 + 4 * 32;

// The format allows 16 and 32 bytes too, but libhdf5 decodes addresses and
// lengths into 64 bits and reads past its buffer on wider ones (found by the
// fuzzer: a version-0 superblock with 16-byte offsets crashed H5Fopen).
bool valid_field_size(unsigned size) {
  return size == 2 || size == 4 || size == 8;
}

// The superblock after its signature (`at` bytes into the file), or a
// problem. `fixed` holds the bytes from the version on, as many as the file has.
std::optional<std::string> superblock_problem(const std::array<unsigned char, kRead>& fixed, std::size_t available,
                                              std::uintmax_t at, std::uintmax_t file_size, std::ifstream& in) {
  auto need = [&](std::size_t bytes) -> std::optional<std::string> {
    if (available >= bytes) return std::nullopt;
    return fmt::format("the superblock at byte {} is cut short: the file ends after {} of its bytes", at,
                       8 + available);
  };
  if (auto cut = need(1)) return cut;
  const unsigned version = fixed[0];
  if (version > 3) return fmt::format("superblock version {} is not one HDF5 defines (0 to 3)", version);
  if (version >= 2) {
    // Version, sizes of offsets and lengths, flags, then four addresses and
    // a checksum (which HDF5 verifies).
    if (auto cut = need(3)) return cut;
    const unsigned offsets = fixed[1];
    const unsigned lengths = fixed[2];
    if (!valid_field_size(offsets))
      return fmt::format("the superblock's size of offsets is {} bytes (2, 4 or 8 are read)", offsets);
    if (!valid_field_size(lengths))
      return fmt::format("the superblock's size of lengths is {} bytes (2, 4 or 8 are read)", lengths);
    const std::uintmax_t size = 8 + 4 + 4 * static_cast<std::uintmax_t>(offsets) + 4;
    if (at + size > file_size) {
      return fmt::format("the superblock at byte {} is cut short: it needs {} bytes, the file has {}", at, size,
                         file_size - at);
    }
    return std::nullopt;
  }
  // Versions 0 and 1: eight one-byte fields, two reserved; two B-tree K
  // values; the consistency flags; (version 1) a third K and two reserved
  // bytes; four addresses and the root group's symbol table entry.
  const std::size_t prefix = version == 0 ? 16 : 20;
  if (auto cut = need(prefix)) return cut;
  const char* names[] = {"free-space storage version", "root group symbol table entry version", "reserved byte 11",
                         "shared header message format version"};
  for (int k = 0; k < 4; ++k) {
    if (fixed[1 + k] != 0) return fmt::format("the superblock's {} is {} (must be 0)", names[k], fixed[1 + k]);
  }
  const unsigned offsets = fixed[5];
  const unsigned lengths = fixed[6];
  if (!valid_field_size(offsets))
    return fmt::format("the superblock's size of offsets is {} bytes (2, 4 or 8 are read)", offsets);
  if (!valid_field_size(lengths))
    return fmt::format("the superblock's size of lengths is {} bytes (2, 4 or 8 are read)", lengths);
  if (fixed[7] != 0) return fmt::format("the superblock's reserved byte 15 is {} (must be 0)", fixed[7]);
  const unsigned leaf_k = fixed[8] | (fixed[9] << 8);
  const unsigned internal_k = fixed[10] | (fixed[11] << 8);
  if (leaf_k == 0 || internal_k == 0) {
    return fmt::format("the superblock's group B-tree K values are {} and {} (must be positive)", leaf_k, internal_k);
  }
  if (version == 1) {
    const unsigned storage_k = fixed[16] | (fixed[17] << 8);
    if (storage_k == 0) return "the superblock's indexed storage B-tree K is 0 (must be positive)";
    if (fixed[18] != 0 || fixed[19] != 0) return "the superblock's reserved bytes 26-27 are not 0";
  }
  // Four addresses and the root group's symbol table entry (two offsets,
  // cache type, reserved, 16-byte scratch pad).
  const std::uintmax_t size = 8 + prefix + 6 * static_cast<std::uintmax_t>(offsets) + 24;
  if (at + size > file_size) {
    return fmt::format("the superblock at byte {} is cut short: it needs {} bytes, the file has {}", at, size,
                       file_size - at);
  }
  // The driver information block (version 0, 3 reserved bytes, the size of
  // its information, an 8-byte driver name, the information) must lie in
  // the file: libhdf5 allocates the size it states before reading it (a
  // 97-byte file stated 1.6 GiB).
  const std::uintmax_t base = decode(&fixed[prefix], offsets);
  const std::uintmax_t driver = decode(&fixed[prefix + 3 * offsets], offsets);
  if (driver == kUndefined) return std::nullopt;
  if (base == kUndefined || base > file_size || driver > file_size - base || file_size - base - driver < 16) {
    return fmt::format("the superblock's driver information block (at byte {}) does not fit in the file of {} bytes",
                       driver, file_size);
  }
  std::array<unsigned char, 8> header{};
  in.clear();
  in.seekg(static_cast<std::streamoff>(base + driver));
  if (!in.read(reinterpret_cast<char*>(header.data()), header.size())) return std::nullopt;
  const std::uintmax_t stated = decode(&header[4], 4);
  if (header[0] != 0) return fmt::format("the driver information block's version is {} (must be 0)", header[0]);
  if (stated > file_size - base - driver - 16) {
    return fmt::format("the driver information block states {} bytes of information, more than the file holds", stated);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> hdf5_superblock_problem(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t file_size = std::filesystem::file_size(path, error);
  if (error) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  // The signature is at byte 0 or after a user block of 512, 1024, 2048, ... bytes.
  for (std::uintmax_t at = 0; at + 8 <= file_size; at = at == 0 ? 512 : 2 * at) {
    std::array<unsigned char, 8> signature{};
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(signature.data()), signature.size())) return std::nullopt;
    if (signature != kSignature) continue;
    std::array<unsigned char, kRead> fixed{};
    in.read(reinterpret_cast<char*>(fixed.data()), fixed.size());
    const auto available = static_cast<std::size_t>(in.gcount());
    return superblock_problem(fixed, available, at, file_size, in);
  }
  return std::nullopt;
}

}  // namespace halfspace::io::detail
