// Private: the group name of a step in a sweep, friction history or film
// history file (docs/file-format.md), shared by their writers and the result
// reader (which the readers' fuzzers build without the writers).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cstddef>
#include <string>

namespace halfspace::io {

// Step `step` of `count`: zero padded to at least three digits, so that the
// names sort in step order.
inline std::string step_group_name(std::size_t step, std::size_t count) {
  const std::size_t digits = std::max<std::size_t>(3, fmt::format("{}", count == 0 ? 0 : count - 1).size());
  return fmt::format("{:0{}}", step, digits);
}

}  // namespace halfspace::io
