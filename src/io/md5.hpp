// Private MD5 digest (RFC 1321), used only to check the checksums that X3P
// files carry for their parts; not for anything security-related.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace halfspace::io::detail {

// The 32 lower-case hex digits of the MD5 digest of `bytes`.
std::string md5_hex(std::string_view bytes);

// The same digest over bytes that arrive in pieces (a member decompressed a
// chunk at a time).
class Md5 {
 public:
  void update(std::string_view bytes);
  std::string hex();  // once, after the last update

 private:
  std::array<std::uint32_t, 4> state_{0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476};
  std::array<unsigned char, 64> pending_{};
  std::size_t pending_size_ = 0;
  std::uint64_t total_ = 0;
};

}  // namespace halfspace::io::detail
