// The ranges the program accepts for physical quantities: the library's
// table (halfspace/physical_ranges.hpp), shared with the Python package,
// under the names the program's files use.
#pragma once

#include "halfspace/physical_ranges.hpp"

namespace halfspace::app {

using halfspace::kMaxLength;
using halfspace::kMaxMeanPressure;
using halfspace::kMaxModulus;
using halfspace::kMinLength;
using halfspace::kMinMeanPressure;
using halfspace::kMinModulus;
using halfspace::require_in_range;

}  // namespace halfspace::app
