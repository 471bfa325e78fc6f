// Option errors and the numbers of messages.
#include "halfspace/error.hpp"

#include <fmt/format.h>

namespace halfspace {

OptionError::OptionError(std::string option, std::string value, std::string rule)
    : InputError(fmt::format("{} = {} {}", option, value, rule)),
      option_(std::move(option)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

std::string format_number(double value) {
  return fmt::format("{:.6g}", value);
}

}  // namespace halfspace
