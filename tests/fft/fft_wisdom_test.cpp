// FFTW wisdom files: where they live, written atomically and read back, and
// corrupt or missing files rejected with a reason while FFTW's wisdom stays
// as it was. The automatic load and save are tested through the program
// (tests/apps/fft_wisdom_cli_test.cpp), one process per run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "halfspace/fft/real_fft.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;
using io::export_fft_wisdom;
using io::fft_wisdom_path;
using io::import_fft_wisdom;
using test::TempDir;

// Every FFTW 3 wisdom export starts so (the version follows).
constexpr std::string_view kWisdomHeader = "(fftw-3";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Sets environment variables for one test and restores them afterwards
// (nullopt: unset).
class ScopedEnvironment {
 public:
  ScopedEnvironment(std::initializer_list<std::pair<const char*, std::optional<std::string>>> values) {
    for (const auto& [name, value] : values) {
      const char* old = std::getenv(name);
      saved_.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
      set(name, value);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;
  ~ScopedEnvironment() {
    for (const auto& [name, value] : saved_) set(name, value);
  }

 private:
  static void set(const char* name, const std::optional<std::string>& value) {
    if (value) {
      ::setenv(name, value->c_str(), 1);
    } else {
      ::unsetenv(name);
    }
  }
  std::vector<std::pair<const char*, std::optional<std::string>>> saved_;
};

// Gives FFTW some wisdom to export: a small measured plan (milliseconds).
void plan_something() {
  const RealFft fft(8, 6, FftPlanning::measure);
}

TEST(FftWisdomTest, PathFollowsEnvironment) {
  {
    const ScopedEnvironment env{{"HALFSPACE_FFTW_WISDOM", "/some/where/wisdom"}, {"XDG_CACHE_HOME", "/cache"}};
    EXPECT_EQ(fft_wisdom_path(), fs::path("/some/where/wisdom"));
  }
  for (const char* off : {"off", ""}) {
    const ScopedEnvironment env{{"HALFSPACE_FFTW_WISDOM", off}, {"XDG_CACHE_HOME", "/cache"}};
    EXPECT_EQ(fft_wisdom_path(), std::nullopt) << "HALFSPACE_FFTW_WISDOM='" << off << "'";
  }
  {
    const ScopedEnvironment env{{"HALFSPACE_FFTW_WISDOM", std::nullopt}, {"XDG_CACHE_HOME", "/cache"}};
    EXPECT_EQ(fft_wisdom_path(), fs::path("/cache/halfspace/fftw-wisdom"));
  }
  {
    // A relative XDG_CACHE_HOME is invalid (XDG Base Directory Specification).
    const ScopedEnvironment env{
        {"HALFSPACE_FFTW_WISDOM", std::nullopt}, {"XDG_CACHE_HOME", "relative"}, {"HOME", "/home/user"}};
    EXPECT_EQ(fft_wisdom_path(), fs::path("/home/user/.cache/halfspace/fftw-wisdom"));
  }
  {
    const ScopedEnvironment env{
        {"HALFSPACE_FFTW_WISDOM", std::nullopt}, {"XDG_CACHE_HOME", std::nullopt}, {"HOME", std::nullopt}};
    EXPECT_EQ(fft_wisdom_path(), std::nullopt);
  }
}

TEST(FftWisdomTest, ExportWritesFileThatImportReadsBack) {
  plan_something();
  const TempDir dir;
  const fs::path path = dir / "cache/halfspace/fftw-wisdom";  // the directories do not exist yet
  std::string problem;
  ASSERT_TRUE(export_fft_wisdom(path, &problem)) << problem;
  const std::string text = read_text(path);
  EXPECT_EQ(text.substr(0, kWisdomHeader.size()), kWisdomHeader) << text;
  EXPECT_EQ(fs::directory_iterator(path.parent_path())->path().filename(), "fftw-wisdom")
      << "the temporary file was left behind";
  EXPECT_TRUE(import_fft_wisdom(path, &problem)) << problem;
}

TEST(FftWisdomTest, CorruptFileIsRejectedAndWisdomKept) {
  plan_something();
  const TempDir dir;
  ASSERT_TRUE(export_fft_wisdom(dir / "before"));
  const std::string good = read_text(dir / "before");
  const std::vector<std::pair<std::string, std::string>> corrupt{
      {"garbage", "this is not wisdom"},
      {"empty", ""},
      {"truncated", good.substr(0, good.size() / 2)},
      {"embedded NUL", std::string("(fftw-3\0", 8) + good},
      {"other version", "(fftw-2.1.5 fftw_wisdom #x0 #x0 #x0 #x0)"},
  };
  for (const auto& [what, text] : corrupt) {
    const fs::path path = dir / "wisdom";
    write_text(path, text);
    std::string problem;
    EXPECT_FALSE(import_fft_wisdom(path, &problem)) << what;
    EXPECT_NE(problem.find(path.string()), std::string::npos) << what << ": " << problem;
    EXPECT_NE(problem.find("not wisdom of this FFTW build"), std::string::npos) << what << ": " << problem;
  }
  ASSERT_TRUE(export_fft_wisdom(dir / "after"));
  EXPECT_EQ(read_text(dir / "after"), good) << "a rejected file changed FFTW's wisdom";
}

TEST(FftWisdomTest, MissingOrUnwritablePathsAreReported) {
  const TempDir dir;
  std::string problem;
  EXPECT_FALSE(import_fft_wisdom(dir / "missing", &problem));
  EXPECT_NE(problem.find("does not exist"), std::string::npos) << problem;

  EXPECT_FALSE(import_fft_wisdom(dir.path(), &problem));
  EXPECT_NE(problem.find("not a regular file"), std::string::npos) << problem;

  // A regular file where the directory should be: cannot be created, whoever runs the test.
  write_text(dir / "file", "x");
  plan_something();
  EXPECT_FALSE(export_fft_wisdom(dir / "file/wisdom", &problem));
  EXPECT_NE(problem.find("cannot create directory"), std::string::npos) << problem;
}

}  // namespace
}  // namespace halfspace
