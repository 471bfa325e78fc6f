// Length units as files write them ("um", "µm", "Micrometer", "nm", ...) and
// their size in metres, for readers of formats that state a unit.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace halfspace::io {

struct LengthUnit {
  std::string name;     // canonical symbol: "m", "mm", "um", "nm", "pm", "Angstrom"
  double metres = 1.0;  // size of one unit in metres
};

// Parses a unit symbol or word: m, mm, um, µm (micro sign or Greek mu), nm,
// pm, Å, and the words metre/meter, millimetre, micrometre, micron,
// nanometre, angstrom (any case, singular or plural). Returns nullopt for
// anything else, including "A" (ampere in Gwyddion files, not angstrom).
std::optional<LengthUnit> parse_length_unit(std::string_view text);

// The same, but throws InputError naming `what` and the accepted units.
LengthUnit require_length_unit(std::string_view text, std::string_view what);

}  // namespace halfspace::io
