// Numeric text tables: line splitting, field splitting, number parsing and
// the per-column printed precision that the profile reader checks x against.
#include "text_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace halfspace::io::detail {
namespace {

std::vector<std::string> split_names(std::string_view line);

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::optional<double> parse_number(std::string_view token) {
  if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Subnormal or overflowing literals: from_chars reports them but strtod
    // gives the correctly rounded value (0, a subnormal, or inf).
    const std::string copy(token);
    char* strtod_end = nullptr;
    value = std::strtod(copy.c_str(), &strtod_end);
    if (strtod_end != copy.c_str() + copy.size()) return std::nullopt;
    return value;
  }
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// The rounding step of a printed number: 10^(exponent - digits after the point).
double printed_step(std::string_view token) {
  int exponent = 0;
  const std::size_t e = token.find_first_of("eE");
  if (e != std::string_view::npos) {
    std::from_chars(token.data() + e + 1 + (e + 1 < token.size() && token[e + 1] == '+' ? 1 : 0),
                    token.data() + token.size(), exponent);
    token = token.substr(0, e);
  }
  const std::size_t point = token.find('.');
  const int decimals = point == std::string_view::npos ? 0 : static_cast<int>(token.size() - point - 1);
  return std::pow(10.0, exponent - decimals);
}

// Column names may hold spaces ("Lateral um", "x [um]"): when the line has a
// comma, semicolon or tab, only those separate names.
std::vector<std::string> split_names(std::string_view line) {
  std::vector<std::string> names;
  if (line.find_first_of(",;\t") == std::string_view::npos) {
    // Space-separated: a unit in brackets belongs to the name before it
    // ("x [um] z [nm]" names two columns, x [um] and z [nm]).
    for (std::string_view field : split_fields(line)) {
      const bool unit = field.size() >= 2 && ((field.front() == '[' && field.back() == ']') ||
                                              (field.front() == '(' && field.back() == ')'));
      if (unit && !names.empty()) {
        names.back() += ' ';
        names.back() += field;
      } else {
        names.emplace_back(field);
      }
    }
    return names;
  }
  std::size_t begin = 0;
  while (begin <= line.size()) {
    std::size_t end = line.find_first_of(",;\t", begin);
    if (end == std::string_view::npos) end = line.size();
    names.emplace_back(trim(line.substr(begin, end - begin)));
    begin = end + 1;
  }
  while (!names.empty() && names.back().empty()) names.pop_back();
  return names;
}

}  // namespace

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const auto is_separator = [](char c) { return c == ',' || c == ';'; };
  bool expect_field = true;  // at the start, or right after a separator
  std::size_t k = 0;
  while (k < line.size()) {
    if (is_blank(line[k])) {
      ++k;
    } else if (is_separator(line[k])) {
      if (expect_field) fields.emplace_back();  // ",," or a leading ","
      expect_field = true;
      ++k;
    } else {
      const std::size_t begin = k;
      while (k < line.size() && !is_blank(line[k]) && !is_separator(line[k])) ++k;
      fields.push_back(line.substr(begin, k - begin));
      expect_field = false;
    }
  }
  // Empty fields at the end (a line ending in "," or ",,") are not data.
  while (!fields.empty() && fields.back().empty()) fields.pop_back();
  return fields;
}

TextTable parse_text_table(std::string_view text, std::size_t first_line, bool allow_header, const ReadTarget& target) {
  if (first_line == 1 && text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  check_is_text(text, 0, target);

  TextTable table;
  std::size_t line_number = first_line - 1;
  std::size_t begin = 0;
  std::vector<std::string_view> fields;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(begin, end - begin));
    begin = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#' || line.front() == '%') continue;

    fields = split_fields(line);
    if (fields.empty()) continue;  // a line of separators only
    const bool first_row = table.rows() == 0 && table.header.empty();
    std::vector<double> row;
    row.reserve(fields.size());
    std::size_t bad = fields.size();
    for (std::size_t f = 0; f < fields.size(); ++f) {
      const std::optional<double> value = fields[f].empty() ? std::nullopt : parse_number(fields[f]);
      if (!value) {
        bad = f;
        break;
      }
      row.push_back(*value);
    }
    if (bad < fields.size()) {
      if (allow_header && first_row) {
        table.header = split_names(line);
        table.header_line = line_number;
        continue;
      }
      if (fields[bad].empty()) {
        target.fail(fmt::format("line {}: field {} is empty (two separators in a row)", line_number, bad + 1));
      }
      target.fail(
          fmt::format("line {}: field {} '{}' is not a number{}", line_number, bad + 1, printable(fields[bad], 40),
                      table.rows() == 0 ? " (comment lines start with # or %; a profile with column names is read with "
                                          "format profile)"
                                        : ""));
    }
    if (table.rows() == 0) {
      table.columns = row.size();
      table.printed_step.assign(table.columns, 0.0);
    } else if (row.size() != table.columns) {
      target.fail(
          fmt::format("line {} has {} values but line {}, the first data line, has {}; every row needs the "
                      "same number of values",
                      line_number, row.size(), table.line_numbers.front(), table.columns));
    }
    for (std::size_t f = 0; f < row.size(); ++f) {
      // A zero's printed digits say nothing about the precision of the
      // others ("0.000000e+00" among "1.000000e-06", ...).
      if (std::isfinite(row[f]) && row[f] != 0.0)
        table.printed_step[f] = std::max(table.printed_step[f], printed_step(fields[f]));
    }
    table.values.insert(table.values.end(), row.begin(), row.end());
    table.line_numbers.push_back(line_number);
  }
  return table;
}

}  // namespace halfspace::io::detail
