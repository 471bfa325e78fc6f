#include "halfspace/io/result_metadata.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "halfspace/surface/statistics.hpp"

namespace halfspace::io {

ResultMetadata result_metadata(const SolveProvenance& run, const Grid& grid, std::span<const double> heights) {
  ResultMetadata metadata = provenance_metadata(run);
  metadata.surface_statistics = surface::surface_statistics(grid, heights);
  return metadata;
}

ResultMetadata provenance_metadata(const SolveProvenance& run) {
  ResultMetadata metadata;
  metadata.e_star = run.e_star;
  metadata.load_mode = std::string(to_string(run.load_mode));
  metadata.threads = run.threads;
  metadata.command_line = run.command_line;
  metadata.config = run.config;
  metadata.height_source = run.height_source;
  metadata.preparation = fmt::format("{}", fmt::join(run.preparation, "\n"));
  return metadata;
}

}  // namespace halfspace::io
