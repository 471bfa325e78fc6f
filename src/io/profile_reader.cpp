// Text profiles: the shared table parser, units from the column names, and the
// uniform-spacing check of the x column against its printed precision.
#include "halfspace/io/profile_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "reader_support.hpp"
#include "text_table.hpp"

namespace halfspace::io {
namespace {

using detail::ReadTarget;

// Room for the rounding of x by whoever wrote the file and of our fit, as a
// multiple of the largest |x|: far below any printed precision.
constexpr double kFitRoundingFactor = 64.0 * std::numeric_limits<double>::epsilon();
// A point half a step off lies as near one grid point as the next: whatever
// the printed precision, no x may be that far off its place.
constexpr double kMaxToleranceInSteps = 0.5;

// The unit in a column name: inside [..] or (..) if present, else its last word.
std::optional<LengthUnit> unit_in_name(std::string_view name) {
  const std::size_t open = name.find_first_of("[(");
  if (open != std::string_view::npos) {
    const std::size_t close = name.find_first_of("])", open + 1);
    if (close != std::string_view::npos) return parse_length_unit(name.substr(open + 1, close - open - 1));
  }
  const std::size_t space = name.find_last_of(" \t_");
  return parse_length_unit(space == std::string_view::npos ? name : name.substr(space + 1));
}

// The part of a Dektak export after its "Scan Data" line, and the scan
// length from its "Length,1500.0 um" line (0 if absent).
struct DektakLayout {
  std::size_t data_offset = 0;
  std::size_t data_line = 1;  // 1-based line number at data_offset
  double length = 0.0;        // as stated, in length_unit
  double length_unit = 1.0;   // metres per unit of length
};

std::optional<DektakLayout> find_dektak_layout(std::string_view text, const ReadTarget& target) {
  if (!text.starts_with("Scan Parameters")) return std::nullopt;
  DektakLayout layout;
  std::size_t begin = 0;
  std::size_t line = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    std::string_view row = text.substr(begin, end - begin);
    while (!row.empty() && (row.back() == '\r' || row.back() == ' ')) row.remove_suffix(1);
    // Past the newline, or at the end when the last line has none.
    begin = std::min(end + 1, text.size());
    ++line;
    if (row.starts_with("Length,")) {
      // "Length,1500.0 um": value and unit separated by a space.
      const std::vector<std::string_view> fields = detail::split_fields(row.substr(7));
      if (fields.size() == 2) {
        const std::optional<LengthUnit> unit = parse_length_unit(fields[1]);
        char* end_of_number = nullptr;
        const std::string number(fields[0]);
        const double value = std::strtod(number.c_str(), &end_of_number);
        if (unit && end_of_number == number.c_str() + number.size()) {
          layout.length = value;
          layout.length_unit = unit->metres;
        }
      }
    }
    if (row == "Scan Data") {
      layout.data_offset = begin;
      layout.data_line = line + 1;
      return layout;
    }
  }
  target.fail("the file starts like a Dektak export ('Scan Parameters') but has no 'Scan Data' line");
}

double median_of(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Names the line that breaks the spacing, if one step (a missing point) or
// one point (a displaced x) does, against the median step: unlike the
// least-squares slope, one bad x cannot move it, so the steps of the other
// points stay within `tolerance` of it (a rounded step takes one of two
// adjacent printed values). Returns without failing when no step stands
// out (a drift, which the caller names).
void fail_at_the_odd_step(const detail::TextTable& table, const ReadTarget& target, double tolerance) {
  const std::size_t n = table.rows();
  std::vector<double> steps(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) steps[k] = table.at(k + 1, 0) - table.at(k, 0);
  const double typical = median_of(steps);
  const auto odd = [&](std::size_t k) { return std::abs(steps[k] - typical) > tolerance; };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!odd(k)) continue;
    const auto line = [&](std::size_t row) { return table.line_numbers[row]; };
    const auto x = [&](std::size_t row) { return table.at(row, 0); };
    if (k + 2 < n && odd(k + 1) && (steps[k] - typical) * (steps[k + 1] - typical) < 0.0) {
      // A step too long then one too short (or the reverse): the point between is displaced.
      target.fail(fmt::format(
          "x is not uniformly spaced: line {} has x = {:.9g}, {:.6g} after line {} (x = {:.9g}) and {:.6g} before "
          "line {} (x = {:.9g}), but the other points step by {:.6g} (the median step), within {:.3g}, the "
          "precision x is printed with (at most half a step); resample the profile to uniform x first",
          line(k + 1), x(k + 1), steps[k], line(k), x(k), steps[k + 1], line(k + 2), x(k + 2), typical, tolerance));
    }
    target.fail(
        fmt::format("x is not uniformly spaced: from line {} (x = {:.9g}) to line {} (x = {:.9g}) x steps by {:.6g} "
                    "but the other points step by {:.6g} (the median step), within {:.3g}, the precision x is "
                    "printed with (at most half a step); resample the profile to uniform x first",
                    line(k), x(k), line(k + 1), x(k + 1), steps[k], typical, tolerance));
  }
}

// The spacing of a uniform x column; throws naming the line off the grid.
double uniform_spacing(const detail::TextTable& table, const ReadTarget& target, double dektak_length) {
  const std::size_t n = table.rows();
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(table.at(k, 0))) {
      target.fail(fmt::format("line {}: x = {:g} is not finite", table.line_numbers[k], table.at(k, 0)));
    }
  }
  // Least squares x_k = a + b k, with k centred for accuracy.
  const double k_mean = 0.5 * static_cast<double>(n - 1);
  double x_mean = 0.0;
  double x_max = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    x_mean += table.at(k, 0);
    x_max = std::max(x_max, std::abs(table.at(k, 0)));
  }
  x_mean /= static_cast<double>(n);
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double dk = static_cast<double>(k) - k_mean;
    sxy += dk * (table.at(k, 0) - x_mean);
    sxx += dk * dk;
  }
  const double slope = sxy / sxx;
  const double intercept = x_mean - slope * k_mean;
  if (!(slope > 0.0)) {
    target.fail(
        fmt::format("x does not increase (from {:.9g} at line {} to {:.9g} at line {}); a profile needs x in "
                    "increasing order",
                    table.at(0, 0), table.line_numbers.front(), table.at(n - 1, 0), table.line_numbers.back()));
  }
  // The printed precision of the nonzero x (text_table skips zeros, whose
  // digits say nothing about the others), never more than half a step.
  const double tolerance =
      std::min(std::max(table.printed_step[0], kFitRoundingFactor * x_max), kMaxToleranceInSteps * slope);
  // Each step may differ from the mean step by the rounding of its two ends.
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double step = table.at(k + 1, 0) - table.at(k, 0);
    if (std::abs(step - slope) > tolerance) {
      fail_at_the_odd_step(table, target, tolerance);
      target.fail(
          fmt::format("x is not uniformly spaced: from line {} (x = {:.9g}) to line {} (x = {:.9g}) x steps by {:.6g} "
                      "but the mean step is {:.6g}, and steps may differ from it only by {:.3g}, the precision "
                      "x is printed with (at most half a step); resample the profile to uniform x first",
                      table.line_numbers[k], table.at(k, 0), table.line_numbers[k + 1], table.at(k + 1, 0), step, slope,
                      tolerance));
    }
  }
  // ... and no point may drift off the uniform grid by more than that precision.
  for (std::size_t k = 0; k < n; ++k) {
    const double expected = intercept + slope * static_cast<double>(k);
    const double deviation = std::abs(table.at(k, 0) - expected);
    if (deviation > tolerance) {
      fail_at_the_odd_step(table, target, tolerance);
      target.fail(fmt::format(
          "x is not uniformly spaced: line {} has x = {:.9g} but the uniform grid fitted to all {} "
          "points (x = {:.9g} + k * {:.9g}) gives {:.9g} there, {:.3g} away, more than "
          "{:.3g}, the precision x is printed with (at most half a step); resample the profile to uniform x first",
          table.line_numbers[k], table.at(k, 0), n, intercept, slope, expected, deviation, tolerance));
    }
  }
  // A stated scan length n * dx is exact where the fitted slope carries the
  // rounding of the printed x; use it when the two agree.
  if (dektak_length > 0.0) {
    const double stated = dektak_length / static_cast<double>(n);
    if (std::abs(stated - slope) * static_cast<double>(n - 1) <= tolerance) return stated;
  }
  return slope;
}

}  // namespace

HeightMap read_profile(const std::filesystem::path& path, const std::optional<LengthUnit>& unit) {
  const ReadTarget target{path, "a text profile"};
  const std::string bytes = detail::read_text_file(target);
  const std::optional<DektakLayout> dektak = find_dektak_layout(bytes, target);
  const std::string_view text = std::string_view(bytes).substr(dektak ? dektak->data_offset : 0);
  const detail::TextTable table =
      detail::parse_text_table(text, dektak ? dektak->data_line : 1, /*allow_header=*/true, target);
  if (table.rows() == 0) target.fail("the file holds no data rows");
  if (table.columns > 2) {
    target.fail(fmt::format("line {} has {} values; a profile has z alone or x and z (for a map use a text matrix)",
                            table.line_numbers.front(), table.columns));
  }
  if (table.rows() < 2) {
    target.fail(fmt::format("the file holds 1 data row (line {}); need at least 2 points", table.line_numbers.front()));
  }

  // Units: the column names' where stated, else the caller's, else metres.
  const bool has_x = table.columns == 2;
  std::vector<std::optional<LengthUnit>> stated(table.columns);
  if (table.header.size() == table.columns) {
    for (std::size_t c = 0; c < table.columns; ++c) stated[c] = unit_in_name(table.header[c]);
  } else if (!table.header.empty()) {
    target.fail(fmt::format("the header on line {} names {} columns but the data have {}", table.header_line,
                            table.header.size(), table.columns));
  }
  std::vector<LengthUnit> units(table.columns, unit.value_or(LengthUnit{"m", 1.0}));
  for (std::size_t c = 0; c < table.columns; ++c) {
    if (!stated[c]) continue;
    if (unit && unit->metres != stated[c]->metres) {
      throw InputError(fmt::format("height map '{}': the unit {} contradicts column '{}' of the file, which is in {}",
                                   path.string(), unit->name, detail::printable(table.header[c]), stated[c]->name));
    }
    units[c] = *stated[c];
  }

  HeightMap map;
  map.dimension = 1;
  map.nx = table.rows();
  map.ny = 1;
  map.heights.resize(static_cast<Eigen::Index>(map.nx));
  const std::size_t z = table.columns - 1;
  for (std::size_t k = 0; k < map.nx; ++k) {
    map.heights[static_cast<Eigen::Index>(k)] = table.at(k, z) * units[z].metres;
  }
  if (has_x) {
    // The stated length in the x column's unit, for the consistency check.
    const double length = dektak ? dektak->length * dektak->length_unit / units[0].metres : 0.0;
    const double spacing = uniform_spacing(table, target, length);
    // A stated length gives dx = length / n computed in metres, as the README does.
    map.dx = length > 0.0 && spacing == length / static_cast<double>(map.nx)
                 ? dektak->length * dektak->length_unit / static_cast<double>(map.nx)
                 : spacing * units[0].metres;
  }
  detail::mark_non_finite_invalid(map);
  map.source = fmt::format("{} ({}profile, {} points, {}z in {})", path.string(), dektak ? "Dektak CSV " : "text ",
                           map.nx, has_x ? fmt::format("x in {}, ", units[0].name) : std::string(), units[z].name);
  return map;
}

}  // namespace halfspace::io
