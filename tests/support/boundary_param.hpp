// Readable names for tests parametrised by the grid boundary
// ("Periodic", "Free" instead of 0 and 1).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "halfspace/grid.hpp"

namespace halfspace::testing {

inline std::string boundary_param_name(const ::testing::TestParamInfo<Boundary>& info) {
  return info.param == Boundary::periodic ? "Periodic" : "Free";
}

}  // namespace halfspace::testing
