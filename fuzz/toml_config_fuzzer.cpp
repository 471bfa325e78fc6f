// libFuzzer harness: the `halfspace solve --config` file read and merged
// into the options (toml++ parsing, key lookup, type and value checks). Bad
// input must end in InputError; anything else is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "halfspace/error.hpp"
#include "solve_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const halfspace::fuzz::InputFile file(data, size);
  halfspace::app::SolveOptions options;
  options.config = file.path();
  try {
    halfspace::app::merge_config_file(options);
  } catch (const halfspace::InputError&) {
  }
  return 0;
}
