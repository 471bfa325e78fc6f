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
// STOP, both included): exactly one must be given. Throws InputError naming
// the option and the rule it broke; every depth is checked (finite, > 0 m),
// and the count (1 to stress::kMaxDepthCount). The grid's range is checked
// once the grid is known (stress::check_depths).
std::vector<double> parse_stress_depths(const std::string* depths, const std::string* depth_range);

// The depths of a list "z1,z2,..." and of a range "START:STOP:COUNT", the
// same rules; `what` names the setting and its value in messages ("--depths
// 1,2" or "stress-depths = 1:2:3 in run.toml").
std::vector<double> parse_depth_list(std::string_view text, const std::string& what);
std::vector<double> parse_depth_range(const std::string& text, const std::string& what);

// Poisson's ratio of `--nu` text; throws InputError naming the option
// unless -1 < nu <= 0.5.
double parse_stress_poisson_ratio(const std::string& text, std::string_view option);

}  // namespace halfspace::app
