// Private MD5 digest (RFC 1321), used only to check the checksums that X3P
// files carry for their parts; not for anything security-related.
#pragma once

#include <string>
#include <string_view>

namespace halfspace::io::detail {

// The 32 lower-case hex digits of the MD5 digest of `bytes`.
std::string md5_hex(std::string_view bytes);

}  // namespace halfspace::io::detail
