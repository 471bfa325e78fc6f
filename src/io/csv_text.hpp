// Private: a table as CSV text, shared by the sweep, friction-history and
// film-history writers (each file's .csv beside its .h5).
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <string>

namespace halfspace::io::detail {

// The header line of `columns`' names, then `rows` lines of `value(row,
// column)`, each number in the shortest form that reads back to the same
// double.
template <class Columns, class Value>
std::string csv_text(const Columns& columns, std::size_t rows, Value&& value) {
  std::string text;
  for (std::size_t c = 0; c < columns.size(); ++c) text += fmt::format("{}{}", c == 0 ? "" : ",", columns[c].name);
  text += '\n';
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) text += fmt::format("{}{}", c == 0 ? "" : ",", value(r, c));
    text += '\n';
  }
  return text;
}

}  // namespace halfspace::io::detail
