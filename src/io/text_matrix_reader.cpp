// Plain-text matrices: the shared table parser, then the shape checks.
#include "halfspace/io/text_matrix_reader.hpp"

#include <fmt/format.h>

#include "reader_support.hpp"
#include "text_table.hpp"

namespace halfspace::io {

HeightMap read_text_matrix(const std::filesystem::path& path, const LengthUnit& unit) {
  const detail::ReadTarget target{path, "a text matrix"};
  const std::string bytes = detail::read_text_file(target);
  const detail::TextTable table = detail::parse_text_table(bytes, 1, /*allow_header=*/false, target);
  if (table.rows() == 0) target.fail("the file holds no numbers");

  HeightMap map;
  const std::size_t rows = table.rows();
  const std::size_t columns = table.columns;
  if (rows == 1 || columns == 1) {
    // One row or one column of numbers: a profile either way.
    map.dimension = 1;
    map.nx = rows * columns;
    map.ny = 1;
  } else {
    map.dimension = 2;
    map.nx = columns;
    map.ny = rows;
  }
  if (map.nx < 2) {
    target.fail(
        fmt::format("the file holds a single number (line {}); need at least 2 points", table.line_numbers.front()));
  }
  map.heights = Eigen::Map<const Eigen::ArrayXd>(table.values.data(), static_cast<Eigen::Index>(table.values.size()));
  if (unit.metres != 1.0) map.heights *= unit.metres;
  detail::mark_non_finite_invalid(map);
  map.source = map.dimension == 1
                   ? fmt::format("{} (text, {} values as a profile, heights in {})", path.string(), map.nx, unit.name)
                   : fmt::format("{} (text matrix, {} rows x {} columns, heights in {})", path.string(), rows, columns,
                                 unit.name);
  return map;
}

}  // namespace halfspace::io
