// MD5 after RFC 1321: 64-byte blocks, four rounds of 16 steps, with the
// per-step shifts and the sine-derived constants of the RFC's section 3.4.
#include "md5.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace halfspace::io::detail {
namespace {

constexpr std::array<std::uint32_t, 64> kShift{7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22,
                                               5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20, 5, 9,  14, 20,
                                               4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23,
                                               6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21};

// floor(2^32 * |sin(k + 1)|), k = 0..63 (RFC 1321, table T).
constexpr std::array<std::uint32_t, 64> kSine{
    0xd76aa478, 0xe8c7b756, 0x242070db, 0xc1bdceee, 0xf57c0faf, 0x4787c62a, 0xa8304613, 0xfd469501,
    0x698098d8, 0x8b44f7af, 0xffff5bb1, 0x895cd7be, 0x6b901122, 0xfd987193, 0xa679438e, 0x49b40821,
    0xf61e2562, 0xc040b340, 0x265e5a51, 0xe9b6c7aa, 0xd62f105d, 0x02441453, 0xd8a1e681, 0xe7d3fbc8,
    0x21e1cde6, 0xc33707d6, 0xf4d50d87, 0x455a14ed, 0xa9e3e905, 0xfcefa3f8, 0x676f02d9, 0x8d2a4c8a,
    0xfffa3942, 0x8771f681, 0x6d9d6122, 0xfde5380c, 0xa4beea44, 0x4bdecfa9, 0xf6bb4b60, 0xbebfbc70,
    0x289b7ec6, 0xeaa127fa, 0xd4ef3085, 0x04881d05, 0xd9d4d039, 0xe6db99e5, 0x1fa27cf8, 0xc4ac5665,
    0xf4292244, 0x432aff97, 0xab9423a7, 0xfc93a039, 0x655b59c3, 0x8f0ccc92, 0xffeff47d, 0x85845dd1,
    0x6fa87e4f, 0xfe2ce6e0, 0xa3014314, 0x4e0811a1, 0xf7537e82, 0xbd3af235, 0x2ad7d2bb, 0xeb86d391};

std::uint32_t rotate_left(std::uint32_t x, std::uint32_t n) {
  return (x << n) | (x >> (32 - n));
}

void process_block(const unsigned char* block, std::array<std::uint32_t, 4>& state) {
  std::array<std::uint32_t, 16> m{};
  for (std::size_t k = 0; k < 16; ++k) {
    m[k] = static_cast<std::uint32_t>(block[4 * k]) | static_cast<std::uint32_t>(block[4 * k + 1]) << 8 |
           static_cast<std::uint32_t>(block[4 * k + 2]) << 16 | static_cast<std::uint32_t>(block[4 * k + 3]) << 24;
  }
  std::uint32_t a = state[0];
  std::uint32_t b = state[1];
  std::uint32_t c = state[2];
  std::uint32_t d = state[3];
  for (std::uint32_t k = 0; k < 64; ++k) {
    std::uint32_t f = 0;
    std::uint32_t g = 0;
    if (k < 16) {
      f = (b & c) | (~b & d);
      g = k;
    } else if (k < 32) {
      f = (d & b) | (~d & c);
      g = (5 * k + 1) % 16;
    } else if (k < 48) {
      f = b ^ c ^ d;
      g = (3 * k + 5) % 16;
    } else {
      f = c ^ (b | ~d);
      g = (7 * k) % 16;
    }
    const std::uint32_t next = d;
    d = c;
    c = b;
    b = b + rotate_left(a + f + kSine[k] + m[g], kShift[k]);
    a = next;
  }
  state[0] += a;
  state[1] += b;
  state[2] += c;
  state[3] += d;
}

}  // namespace

void Md5::update(std::string_view bytes) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t size = bytes.size();
  total_ += size;
  if (pending_size_ > 0) {
    const std::size_t take = std::min(size, pending_.size() - pending_size_);
    std::memcpy(pending_.data() + pending_size_, data, take);
    pending_size_ += take;
    data += take;
    size -= take;
    if (pending_size_ < pending_.size()) return;
    process_block(pending_.data(), state_);
    pending_size_ = 0;
  }
  for (; size >= 64; data += 64, size -= 64) process_block(data, state_);
  std::memcpy(pending_.data(), data, size);
  pending_size_ = size;
}

std::string Md5::hex() {
  // Padding: 0x80, zeros to 56 mod 64, then the length in bits (64-bit LE).
  std::array<unsigned char, 128> tail{};
  std::memcpy(tail.data(), pending_.data(), pending_size_);
  tail[pending_size_] = 0x80;
  const std::size_t tail_size = pending_size_ < 56 ? 64 : 128;
  const std::uint64_t bits = total_ * 8;
  for (std::size_t k = 0; k < 8; ++k) tail[tail_size - 8 + k] = static_cast<unsigned char>(bits >> (8 * k));
  for (std::size_t offset = 0; offset < tail_size; offset += 64) process_block(tail.data() + offset, state_);

  std::string hex;
  for (const std::uint32_t word : state_) {
    for (std::size_t k = 0; k < 4; ++k) hex += fmt::format("{:02x}", (word >> (8 * k)) & 0xff);
  }
  return hex;
}

std::string md5_hex(std::string_view bytes) {
  Md5 digest;
  digest.update(bytes);
  return digest.hex();
}

}  // namespace halfspace::io::detail
