// A front end that writes options as flags ("--name value"), for the
// messages of the problem builders' tests (problem.hpp,
// lubrication/lubrication_problem.hpp).
#pragma once

#include <string>
#include <string_view>

#include "halfspace/problem.hpp"

namespace halfspace::testing {

class FlagSpelling : public OptionSpelling {
 public:
  std::string name(std::string_view option) const override { return "--" + std::string(option); }
  std::string describe(std::string_view option, std::string_view value) const override {
    return name(option) + " " + std::string(value);
  }
};

}  // namespace halfspace::testing
