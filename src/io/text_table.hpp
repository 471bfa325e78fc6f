// Private parser of numeric text tables, shared by the text-matrix and the
// profile readers: comment lines, whitespace/comma/semicolon separators, an
// optional header line of column names, and errors that name the line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "reader_support.hpp"

namespace halfspace::io::detail {

struct TextTable {
  std::size_t columns = 0;
  std::vector<double> values;             // row-major, rows() * columns
  std::vector<std::size_t> line_numbers;  // 1-based line of each row in the file
  std::vector<std::string> header;        // column names, when a header line preceded the data
  std::size_t header_line = 0;            // its 1-based line number, 0 if none
  // Per column, the largest rounding step of the values as printed: 0.1 for
  // "12.3", 1e-7 for "1.5e-6", 1 for "42". Non-finite values and zeros do
  // not count (0 for a column of zeros).
  std::vector<double> printed_step;

  std::size_t rows() const { return line_numbers.size(); }
  double at(std::size_t row, std::size_t column) const { return values[row * columns + column]; }
};

// Parses `text` (the file, or its part from `first_line`, 1-based) as rows of
// numbers. Rules:
// - lines whose first non-blank character is '#' or '%' are comments; blank
//   lines are skipped; "\r\n" and "\n" endings and a UTF-8 byte-order mark
//   are accepted;
// - fields are separated by whitespace, or by one ',' or ';' with optional
//   whitespace around it; empty fields at the end of a line are ignored (some
//   instruments end every line with ","), an empty field elsewhere is an error;
// - numbers are read by std::from_chars (round-trip exact; "nan" and "inf"
//   are accepted and become invalid points later); a leading '+' is allowed;
// - when `allow_header`, the first non-comment line may hold column names
//   (any field that is not a number makes it the header);
// - every data row must have the same number of fields.
// Binary content (a NUL or other control byte) is reported as "not text".
TextTable parse_text_table(std::string_view text, std::size_t first_line, bool allow_header, const ReadTarget& target);

// Splits one line into fields by the rules above (without the number check).
std::vector<std::string_view> split_fields(std::string_view line);

}  // namespace halfspace::io::detail
