// `halfspace stress`: the subsurface stress field of a solved contact, read
// from a result file, written to a file of its own (docs/usage.md#stress).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "command.hpp"

namespace halfspace::app {

// Registers `stress` on the program's parser.
Command add_stress_command(CLI::App& program);

// The depths of `--depths z1,z2,...` (text of `depths`, if given) or
// `--depth-range START:STOP:COUNT` (COUNT evenly spaced depths from START to
// STOP, both included): exactly one must be given. `prefix` is the option
// family ("" or "stress-" for solve). Throws InputError naming the option
// and the rule it broke; every depth is checked (finite, > 0 m), and the
// count (1 to stress::kMaxDepthCount).
std::vector<double> parse_stress_depths(const std::string* depths, const std::string* depth_range,
                                        std::string_view prefix = "");

// Poisson's ratio of `--nu` text; throws InputError naming the option
// unless -1 < nu <= 0.5.
double parse_stress_poisson_ratio(const std::string& text, std::string_view option);

// The message when Poisson's ratio is missing.
std::string missing_poisson_ratio_message(std::string_view option);

}  // namespace halfspace::app
