// libFuzzer harness: the result-file readers (halfspace::io::read_result, as
// `halfspace stress` and Python's read_result use it, and
// read_result_pressure) on arbitrary bytes. Bad input must end in
// InputError (FileError is one); any other exception, a crash or a
// sanitizer report is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/result_pressure_reader.hpp"
#include "halfspace/io/result_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace halfspace;
  const fuzz::InputFile file(data, size);
  try {
    const io::StoredResult stored = io::read_result(file.path());
    if (stored.height.size() != stored.pressure.size()) __builtin_trap();
  } catch (const InputError&) {
  }
  try {
    const io::ResultPressure result = io::read_result_pressure(file.path());
    if (result.pressure.size() != result.grid.size()) __builtin_trap();
  } catch (const InputError&) {
  }
  return 0;
}
