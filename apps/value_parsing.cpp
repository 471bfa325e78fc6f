// Strict text-to-value parsing for the command line: a value must be consumed
// entirely ("10N" or "1e-3m" is an error, not 10 or 1e-3), so typos never pass.
#include "value_parsing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

#include "halfspace/error.hpp"

namespace halfspace::app {
namespace {

// std::from_chars rejects a leading '+', which people write for exponents'
// mantissas ("+1e3") often enough to accept it.
std::string_view without_plus(std::string_view text) {
  return (text.size() > 1 && text.front() == '+') ? text.substr(1) : text;
}

// The parts of `text` between `separator`s (one part when there is none).
std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k == text.size() || text[k] == separator) {
      parts.push_back(text.substr(start, k - start));
      start = k + 1;
    }
  }
  return parts;
}

// One step "X" or "X,Y" of a tangential load.
std::array<double, 2> parse_step(std::string_view text, std::string_view what) {
  const std::vector<std::string_view> parts = split(text, ',');
  if (parts.size() > 2) {
    throw InputError(fmt::format(
        "{} is invalid: step '{}' has more than two components; a step is X or X,Y, and the steps of a history are "
        "separated by ';' (e.g. '0;0.5;1' along x, quoted for the shell)",
        what, text));
  }
  return {parse_number(parts[0], what), parts.size() == 2 ? parse_number(parts[1], what) : 0.0};
}

bool is_shell_safe(char c) {
  const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
  return alnum || std::string_view("@%+=:,./_-").find(c) != std::string_view::npos;
}

}  // namespace

double parse_number(std::string_view text, std::string_view what) {
  const std::string_view digits = without_plus(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
    throw InputError(fmt::format("{} is invalid: expected a finite number", what));
  }
  return value;
}

long long parse_integer(std::string_view text, std::string_view what) {
  const std::string_view digits = without_plus(text);
  long long value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
    throw InputError(fmt::format("{} is invalid: expected a whole number", what));
  }
  return value;
}

double parse_memory_size(std::string_view text, std::string_view what) {
  const auto invalid = [&] {
    return InputError(fmt::format(
        "{} is invalid: expected a size in bytes, or with a unit K, M, G or T (powers of 1024), e.g. 512M or 8G",
        what));
  };
  std::string_view number = text;
  double unit = 1.0;
  for (std::string_view suffix : {"iB", "B"}) {
    if (number.size() > suffix.size() && number.substr(number.size() - suffix.size()) == suffix) {
      number.remove_suffix(suffix.size());
      break;
    }
  }
  constexpr std::string_view kUnits = "KMGT";
  if (!number.empty()) {
    const char last =
        static_cast<char>(number.back() >= 'a' && number.back() <= 'z' ? number.back() - 'a' + 'A' : number.back());
    if (const std::size_t power = kUnits.find(last); power != std::string_view::npos) {
      unit = std::pow(1024.0, static_cast<double>(power + 1));
      number.remove_suffix(1);
    } else if (number.size() != text.size() && text.substr(number.size()) != "B") {
      throw invalid();  // "iB" without a unit letter
    }
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || error != std::errc() || end != number.data() + number.size()) throw invalid();
  const double bytes = value * unit;
  if (!(std::isfinite(bytes) && bytes >= 1.0)) {
    throw InputError(fmt::format("{} is invalid: the size must be at least 1 byte and finite", what));
  }
  return bytes;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view what) {
  const auto trimmed = [](std::string_view part) {
    while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
    while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
    return part;
  };
  const auto number = [&](std::string_view part) {
    const std::string_view value = trimmed(part);
    const std::string_view digits = without_plus(value);
    double result = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), result);
    if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(result)) {
      throw InputError(fmt::format("{} is invalid: '{}' is not a finite number", what, value));
    }
    return result;
  };

  const bool is_list = text.find(',') != std::string_view::npos;
  const bool is_range = text.find(':') != std::string_view::npos;
  if (!is_list && !is_range) return {parse_number(text, what)};
  if (is_list && is_range) {
    throw InputError(fmt::format("{} is invalid: give a list A,B,C or a range START:STOP:COUNT, not both", what));
  }
  if (is_list) {
    std::vector<double> values;
    for (std::string_view part : split(text, ',')) values.push_back(number(part));
    return values;
  }
  const std::vector<std::string_view> parts = split(text, ':');
  if (parts.size() != 3) {
    throw InputError(fmt::format("{} is invalid: a range is START:STOP:COUNT, e.g. 1e5:1e7:10", what));
  }
  const double start = number(parts[0]);
  const double stop = number(parts[1]);
  const long long count = parse_integer(trimmed(parts[2]), what);
  if (count < 2 || count > kMaxListValues) {
    throw InputError(
        fmt::format("{} is invalid: the range needs a COUNT from 2 to {} (got {})", what, kMaxListValues, count));
  }
  if (!(start > 0.0 && stop > 0.0)) {
    throw InputError(fmt::format("{} is invalid: a range is log-spaced, so START and STOP must be positive", what));
  }
  // Each value from its index (no accumulated rounding); the ends exactly.
  std::vector<double> values(static_cast<std::size_t>(count));
  const double ratio = std::log(stop / start);
  for (long long k = 0; k < count; ++k) {
    values[static_cast<std::size_t>(k)] =
        start * std::exp(ratio * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  values.front() = start;
  values.back() = stop;
  return values;
}

std::vector<std::array<double, 2>> parse_tangential_steps(std::string_view text, std::string_view what) {
  std::vector<std::array<double, 2>> steps;
  const auto add = [&](double x, double y) {
    if (static_cast<long long>(steps.size()) >= kMaxListValues) {
      throw InputError(fmt::format("{} is invalid: more than {} steps", what, kMaxListValues));
    }
    steps.push_back({x, y});
  };
  for (std::string_view part : split(text, ';')) {
    if (part.empty())
      throw InputError(fmt::format("{} is invalid: an empty step (two ';' in a row, or at an end)", what));
    const std::vector<std::string_view> range = split(part, ':');
    if (range.size() == 1) {
      const auto [x, y] = parse_step(part, what);
      add(x, y);
      continue;
    }
    if (range.size() != 3) {
      throw InputError(fmt::format("{} is invalid: '{}' is not a range START:STOP:COUNT", what, part));
    }
    const auto [x0, y0] = parse_step(range[0], what);
    const auto [x1, y1] = parse_step(range[1], what);
    const long long count = parse_integer(range[2], what);
    if (count < 2 || count > kMaxListValues) {
      throw InputError(
          fmt::format("{} is invalid: the COUNT of range '{}' must be 2 to {}", what, part, kMaxListValues));
    }
    for (long long k = 0; k < count; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(count - 1);
      // The ends exactly, the steps between evenly spaced.
      add(k + 1 == count ? x1 : x0 + t * (x1 - x0), k + 1 == count ? y1 : y0 + t * (y1 - y0));
    }
  }
  return steps;
}

std::string join_command_line(const std::vector<std::string>& arguments) {
  std::string line;
  for (const std::string& argument : arguments) {
    if (!line.empty()) line += ' ';
    const bool safe = !argument.empty() && std::all_of(argument.begin(), argument.end(), is_shell_safe);
    if (safe) {
      line += argument;
      continue;
    }
    // Single quotes keep everything literal; a quote itself is closed, escaped
    // and reopened: ' -> '\''.
    line += '\'';
    for (char c : argument) {
      if (c == '\'') {
        line += "'\\''";
      } else {
        line += c;
      }
    }
    line += '\'';
  }
  return line;
}

}  // namespace halfspace::app
