// A benchmark argument's comma-separated numbers: "16,32" -> {16, 32}.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace halfspace::bench {

inline std::vector<double> number_list(std::string_view text) {
  std::vector<double> values;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    values.push_back(std::atof(std::string(text.substr(start, comma - start)).c_str()));
    start = comma + 1;
  }
  return values;
}

}  // namespace halfspace::bench
