// Strict parsers for command-line values (numbers, memory sizes, lists,
// tangential load steps) and shell quoting of the command line recorded in
// output files.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace halfspace::app {

// The whole of `text` as a finite double ("1e-3", "+2", "0.5"). Throws
// InputError "`what` is not a finite number" otherwise; `what` names the
// setting, e.g. "--force abc".
double parse_number(std::string_view text, std::string_view what);

// The whole of `text` as a decimal integer. Throws InputError otherwise.
long long parse_integer(std::string_view text, std::string_view what);

// A memory size: a whole number of bytes ("1000000000"), or a number with
// one of the binary units K, M, G, T, each optionally followed by "iB" or
// "B" ("512M", "1.5G", "8GiB"; K = 1024 bytes). Returns bytes. Throws
// InputError naming `what` unless positive and finite.
double parse_memory_size(std::string_view text, std::string_view what);

// Largest number of values a range START:STOP:COUNT may expand to.
inline constexpr long long kMaxListValues = 10000;

// One number ("1e5"), a comma-separated list ("1e5,2e5,5e5") or a log-spaced
// range "START:STOP:COUNT" of COUNT >= 2 values from START to STOP, both
// included and positive (1e5:1e7:3 is 1e5, 1e6, 1e7). Signs are not checked
// otherwise. A single number fails exactly as parse_number does. Throws
// InputError naming `what` and the offending part.
std::vector<double> parse_number_list(std::string_view text, std::string_view what);

// Tangential load steps as written: steps separated by ';', each "X" or
// "X,Y" (y = 0 when omitted), or a range "START:STOP:COUNT" of COUNT >= 2
// evenly spaced steps from START to STOP, both included, whose ends are "X"
// or "X,Y" ("0:1:5;1:-1:9"). Returns each step's (x, y). Throws InputError
// naming `what` and the offending part.
std::vector<std::array<double, 2>> parse_tangential_steps(std::string_view text, std::string_view what);

// `arguments` joined by spaces, each quoted for a POSIX shell where needed,
// so that the recorded command line can be pasted back into a terminal.
std::string join_command_line(const std::vector<std::string>& arguments);

}  // namespace halfspace::app
