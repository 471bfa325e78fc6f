// A front end that writes options as flags ("--name value"), and the
// message of a refusal, for the messages of the problem builders' tests (problem.hpp,
// lubrication/lubrication_problem.hpp).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "halfspace/error.hpp"
#include "halfspace/problem.hpp"

namespace halfspace::testing {

class FlagSpelling : public OptionSpelling {
 public:
  std::string name(std::string_view option) const override { return "--" + std::string(option); }
  std::string describe(std::string_view option, std::string_view value) const override {
    return name(option) + " " + std::string(value);
  }
};

// The message of the InputError `make` throws; empty (and a failure) if none.
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

}  // namespace halfspace::testing
