// Hostile inputs through the real executable: endless devices as height map
// and config, an unreadable /proc file, and a damaged HDF5 file. Each must end
// in exit 1 with one line on stderr naming the file, and write nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "io/reader_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

void expect_one_line_input_error(const std::vector<std::string>& arguments, const std::vector<std::string>& parts) {
  const TempDir dir;
  std::vector<std::string> all = arguments;
  for (const char* extra : {"--E-star", "1e9", "--force", "1e-9", "--threads", "1", "--quiet", "--output"}) {
    all.emplace_back(extra);
  }
  all.push_back((dir / "out.h5").string());
  testing::expect_input_error(testing::run(all, dir), parts, dir / "out.h5");
}

TEST(HostileInputCliTest, DevZeroAsHeightMapOrConfigIsRefusedAtOnce) {
  // Both used to read /dev/zero until memory ran out.
  expect_one_line_input_error({"solve", "--height-map", "/dev/zero", "--format", "npy", "--dx", "1e-6", "--dy", "1e-6"},
                              {"/dev/zero", "magic"});
  expect_one_line_input_error({"solve", "--config", "/dev/zero"},
                              {"config file /dev/zero is larger than 1048576 bytes (1 MiB)"});
}

TEST(HostileInputCliTest, AConfigWithACodePointTomlPlusPlusMishandlesIsAParseError) {
  // U+0344 in a bare key: toml++ 3.3.0 reaches an "unreachable" branch of its
  // whitespace table (found by fuzz/toml_config_fuzzer.cpp); the library
  // halfspace links must still report a parse error.
  const TempDir dir;
  const fs::path config = dir / "odd.toml";
  test::write_bytes(config, "isz\xcd\x84ui");
  expect_one_line_input_error({"solve", "--config", config.string()}, {config.string(), "is not valid TOML"});
}

TEST(HostileInputCliTest, AnUnreadableFileIsNamed) {
  // Used to print "basic_filebuf::underflow error reading the file", no name.
  expect_one_line_input_error(
      {"solve", "--height-map", "/proc/self/mem", "--format", "matrix", "--dx", "1e-6", "--dy", "1e-6"},
      {"/proc/self/mem", "cannot be read"});
}

TEST(HostileInputCliTest, ADamagedHdf5FileGivesOneLine) {
  // HDF5 used to print "HDF5: infinite loop closing library" and a line of
  // interface names at exit, after halfspace's message.
  const TempDir dir;
  std::string bytes = test::read_bytes(test::kFormatDataDir / "di-5-crop-48x64.h5");
  bytes[1410] = '\x94';  // an object address: H5Fopen fails with "addr overflow"
  const fs::path damaged = dir / "damaged.h5";
  test::write_bytes(damaged, bytes);
  expect_one_line_input_error({"solve", "--height-map", damaged.string()}, {damaged.string()});
}

}  // namespace
}  // namespace halfspace
