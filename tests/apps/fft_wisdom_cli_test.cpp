// FFTW wisdom through the program, one process per run as in real use: a
// measured run writes the wisdom file named by HALFSPACE_FFTW_WISDOM, the
// next run reads it (and, having nothing new, leaves it alone), a corrupt
// file is ignored without a word and replaced, and "off" writes nothing.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5_test_support.hpp"
#include "support/cli_checks.hpp"
#include "support/program_run.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::run_program;

// Every FFTW 3 wisdom export starts so (the version follows).
constexpr std::string_view kWisdomHeader = "(fftw-3";

// A small periodic solve (16 x 16, one thread) with measured FFT plans.
std::vector<std::string> measured_solve(const fs::path& output) {
  const std::vector<std::pair<std::string, std::string>> options{
      {"--geometry", "wavy"}, {"--wavelength", "1e-3"},      {"--amplitude", "1e-6"},      {"--grid", "16x16"},
      {"--size", "1e-3"},     {"--boundary", "periodic"},    {"--E-star", "1e11"},         {"--mean-pressure", "3e7"},
      {"--threads", "1"},     {"--fft-planning", "measure"}, {"--output", output.string()}};
  std::vector<std::string> arguments{"solve", "--quiet"};
  for (const auto& [flag, value] : options) {
    arguments.push_back(flag);
    arguments.push_back(value);
  }
  return arguments;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ino_t inode(const fs::path& path) {
  struct stat status {};
  return ::stat(path.c_str(), &status) == 0 ? status.st_ino : 0;
}

TEST(FftWisdomCliTest, MeasuredRunSavesWisdomAndNextRunReadsIt) {
  const TempDir dir;
  const fs::path wisdom = dir / "cache/fftw-wisdom";
  const auto first =
      run_program(measured_solve(dir / "a.h5"), dir.path(), {{"HALFSPACE_FFTW_WISDOM", wisdom.string()}});
  ASSERT_EQ(first.exit_code, testing::kExitOk) << first.err;
  EXPECT_EQ(first.err, "");
  const std::string text = read_text(wisdom);
  ASSERT_EQ(text.substr(0, kWisdomHeader.size()), kWisdomHeader) << text;

  // Wisdom is saved by renaming a new file onto the old one, so an unchanged
  // inode means the second run found every plan in the file and saved nothing.
  const ino_t before = inode(wisdom);
  const auto second =
      run_program(measured_solve(dir / "b.h5"), dir.path(), {{"HALFSPACE_FFTW_WISDOM", wisdom.string()}});
  ASSERT_EQ(second.exit_code, testing::kExitOk) << second.err;
  EXPECT_EQ(inode(wisdom), before) << "the second run did not use the saved wisdom";
  EXPECT_EQ(read_text(wisdom), text);
  for (const auto& entry : fs::directory_iterator(wisdom.parent_path())) {
    EXPECT_EQ(entry.path().filename(), "fftw-wisdom") << "left behind: " << entry.path();
  }
}

TEST(FftWisdomCliTest, CorruptWisdomFileIsIgnoredAndReplaced) {
  const TempDir dir;
  const fs::path wisdom = dir / "fftw-wisdom";
  std::ofstream(wisdom) << "(fftw-3.3.10 fftw_wisdom #x0 garbage";
  const auto run =
      run_program(measured_solve(dir / "out.h5"), dir.path(), {{"HALFSPACE_FFTW_WISDOM", wisdom.string()}});
  ASSERT_EQ(run.exit_code, testing::kExitOk) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_TRUE(fs::exists(dir / "out.h5"));
  const std::string text = read_text(wisdom);
  EXPECT_EQ(text.substr(0, kWisdomHeader.size()), kWisdomHeader) << text;
  EXPECT_EQ(text.find("garbage"), std::string::npos) << text;
}

TEST(FftWisdomCliTest, OffWritesNoWisdom) {
  const TempDir dir;
  for (const char* off : {"off", ""}) {
    const auto run = run_program(
        measured_solve(dir / "out.h5"), dir.path(),
        {{"HALFSPACE_FFTW_WISDOM", off}, {"XDG_CACHE_HOME", (dir / "cache").string()}, {"HOME", dir.path().string()}});
    ASSERT_EQ(run.exit_code, testing::kExitOk) << run.err;
    EXPECT_FALSE(fs::exists(dir / "cache")) << "HALFSPACE_FFTW_WISDOM='" << off << "'";
    EXPECT_FALSE(fs::exists(dir / ".cache")) << "HALFSPACE_FFTW_WISDOM='" << off << "'";
  }
}

}  // namespace
}  // namespace halfspace
