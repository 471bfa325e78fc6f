// libFuzzer harness: halfspace::io::read_gsf_height_map on arbitrary bytes. Bad input
// must end in InputError (FileError is one); any other exception, a crash or a
// sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fuzz_input.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/gsf_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace halfspace;
  const fuzz::InputFile file(data, size);
  try {
    const HeightMap map = io::read_gsf_height_map(file.path(), std::nullopt);
    if (map.heights.size() != static_cast<Eigen::Index>(map.size())) __builtin_trap();
  } catch (const InputError&) {
  }
  return 0;
}
