// Refusing a run that would need more memory than the machine has (or than
// --max-memory allows) before it allocates anything: the estimate comes from
// halfspace/memory_estimate.hpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace halfspace::app {

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  // "--max-memory 8G", or where the available memory was read
  bool given = false;  // by --max-memory (or its config key)
};

// The limit a run must stay under: `max_memory` (the option's text, parsed
// with parse_memory_size; `what` names it, e.g. "--max-memory 8G") when
// given, else the memory available now. Nothing when neither is known.
std::optional<MemoryLimit> memory_limit(const std::optional<std::string>& max_memory, const std::string& what);

// Throws InputError unless `estimate` bytes fit in `limit`: "<request> needs
// about 93.1 TiB of memory at its peak, but 19.9 GiB is available
// (MemAvailable in /proc/meminfo): ...". `request` names the option or file
// and the grid, e.g. "--grid 1000000x1000000: a solve on 1e+12 cells (...)".
void require_memory(std::string_view request, double estimate, const std::optional<MemoryLimit>& limit);

}  // namespace halfspace::app
