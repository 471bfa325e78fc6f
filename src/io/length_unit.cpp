// Length units: one table from every accepted spelling to metres.
#include "halfspace/io/length_unit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "halfspace/error.hpp"

namespace halfspace::io {
namespace {

struct Spelling {
  std::string_view text;
  std::string_view name;
  double metres;
};

// Symbols are matched exactly (case matters: "mm" is not "Mm").
constexpr std::array kSymbols{
    Spelling{"m", "m", 1.0},
    Spelling{"mm", "mm", 1e-3},
    Spelling{"um", "um", 1e-6},
    Spelling{"\xC2\xB5m", "um", 1e-6},  // micro sign U+00B5
    Spelling{"\xCE\xBCm", "um", 1e-6},  // Greek mu U+03BC
    Spelling{"nm", "nm", 1e-9},
    Spelling{"pm", "pm", 1e-12},
    Spelling{"\xC3\x85", "Angstrom", 1e-10},      // Å U+00C5
    Spelling{"\xE2\x84\xAB", "Angstrom", 1e-10},  // Å U+212B
};

// Words are matched in lower case, singular or plural.
constexpr std::array kWords{
    Spelling{"meter", "m", 1.0},        Spelling{"metre", "m", 1.0},        Spelling{"millimeter", "mm", 1e-3},
    Spelling{"millimetre", "mm", 1e-3}, Spelling{"micrometer", "um", 1e-6}, Spelling{"micrometre", "um", 1e-6},
    Spelling{"micron", "um", 1e-6},     Spelling{"nanometer", "nm", 1e-9},  Spelling{"nanometre", "nm", 1e-9},
    Spelling{"picometer", "pm", 1e-12}, Spelling{"picometre", "pm", 1e-12}, Spelling{"angstrom", "Angstrom", 1e-10},
};

std::string_view trim(std::string_view text) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

}  // namespace

std::optional<LengthUnit> parse_length_unit(std::string_view text) {
  text = trim(text);
  for (const Spelling& symbol : kSymbols) {
    if (text == symbol.text) return LengthUnit{std::string(symbol.name), symbol.metres};
  }
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  if (lower.size() > 1 && lower.back() == 's') lower.pop_back();
  for (const Spelling& word : kWords) {
    if (lower == word.text) return LengthUnit{std::string(word.name), word.metres};
  }
  return std::nullopt;
}

LengthUnit require_length_unit(std::string_view text, std::string_view what) {
  if (auto unit = parse_length_unit(text)) return *unit;
  throw InputError(fmt::format("{} '{}' is not a length unit: use m, mm, um, nm, pm or Angstrom", what, text));
}

}  // namespace halfspace::io
