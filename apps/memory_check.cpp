// The memory limit of a run and the refusal when the estimate exceeds it.
#include "memory_check.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"
#include "halfspace/memory_estimate.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {

std::optional<MemoryLimit> memory_limit(const std::optional<std::string>& max_memory, const std::string& what) {
  if (max_memory) return MemoryLimit{parse_memory_size(*max_memory, what), what, true};
  if (const std::optional<AvailableMemory> available = available_memory()) {
    return MemoryLimit{available->bytes, available->source, false};
  }
  return std::nullopt;
}

void require_memory(std::string_view request, double estimate, const std::optional<MemoryLimit>& limit) {
  if (!limit || estimate <= limit->bytes) return;
  if (limit->given) {
    throw InputError(fmt::format(
        "{} needs about {} of memory at its peak, more than the {} that {} allows: use a smaller grid, or a larger "
        "--max-memory if the machine has the memory",
        request, format_bytes(estimate), format_bytes(limit->bytes), limit->source));
  }
  throw InputError(
      fmt::format("{} needs about {} of memory at its peak, but {} is available ({}): use a smaller grid, or pass "
                  "--max-memory SIZE to set the limit yourself",
                  request, format_bytes(estimate), format_bytes(limit->bytes), limit->source));
}

}  // namespace halfspace::app
