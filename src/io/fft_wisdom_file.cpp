// The FFTW wisdom file: where it lives, read with every failure named,
// written atomically like every output, and installed as the store of
// measured planning (fft/fft_wisdom.hpp).
#include "halfspace/io/fft_wisdom_file.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/fft/fft_wisdom.hpp"
#include "halfspace/io/output_file.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;

// Wisdom for a handful of sizes is a few kilobytes; a file this large is not
// wisdom, and is not read into memory.
constexpr std::uintmax_t kMaxWisdomBytes = std::uintmax_t{16} << 20;

// The text in `path`; nullopt with `problem` saying why if it cannot be read
// (`missing` tells a file that does not exist, the normal first run).
std::optional<std::string> read_wisdom(const fs::path& path, std::string& problem, bool& missing) {
  const std::string shown = path.string();
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  missing = !fs::exists(status);
  if (missing) {
    problem = fmt::format("wisdom file '{}' does not exist", shown);
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) {
    problem = fmt::format("wisdom file '{}' is not a regular file", shown);
    return std::nullopt;
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error || size > kMaxWisdomBytes) {
    problem = fmt::format("wisdom file '{}' is larger than {} bytes", shown, kMaxWisdomBytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    problem = fmt::format("wisdom file '{}' cannot be read", shown);
    return std::nullopt;
  }
  return text.str();
}

// Written like every output (output_file.hpp): under a temporary name and
// renamed, so runs side by side never see a partial file, and never onto a
// device, FIFO or directory.
bool write_wisdom(const fs::path& path, const std::string& wisdom, std::string& problem) {
  std::error_code error;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), error);
    if (error) {
      problem = fmt::format("cannot create directory '{}' for the wisdom file: {}", path.parent_path().string(),
                            error.message());
      return false;
    }
  }
  try {
    write_output_file(path, wisdom);
  } catch (const FileError& failure) {
    problem = fmt::format("wisdom not saved: {}", failure.what());
    return false;
  }
  return true;
}

// The file at `path`, and the single-precision plans' beside it.
class WisdomFile final : public fft::FftWisdomStore {
 public:
  explicit WisdomFile(fs::path path) : path_(std::move(path)) {}

  fs::path location(bool single) const override {
    fs::path where = path_;
    if (single) where += "-single";
    return where;
  }
  std::optional<std::string> load(bool single, std::string& problem) const override {
    bool missing = false;
    std::optional<std::string> text = read_wisdom(location(single), problem, missing);
    if (missing) problem.clear();
    return text;
  }
  bool save(bool single, const std::string& text, std::string& problem) const override {
    return write_wisdom(location(single), text, problem);
  }

 private:
  fs::path path_;
};

void set_problem(std::string* problem, std::string text) {
  if (problem != nullptr) *problem = std::move(text);
}

}  // namespace

std::optional<fs::path> fft_wisdom_path() {
  if (const char* chosen = std::getenv("HALFSPACE_FFTW_WISDOM")) {
    const std::string_view text(chosen);
    if (text.empty() || text == "off") return std::nullopt;
    return fs::path(text);
  }
  // XDG Base Directory Specification: a relative XDG_CACHE_HOME is invalid
  // and must be ignored.
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache != nullptr && fs::path(cache).is_absolute()) {
    return fs::path(cache) / "halfspace" / "fftw-wisdom";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return fs::path(home) / ".cache" / "halfspace" / "fftw-wisdom";
  }
  return std::nullopt;
}

void use_fft_wisdom_file() {
  const std::optional<fs::path> path = fft_wisdom_path();
  fft::set_fft_wisdom_store(path ? std::make_shared<WisdomFile>(*path) : nullptr);
}

bool import_fft_wisdom(const fs::path& path, std::string* problem) {
  std::string failure;
  bool missing = false;
  const std::optional<std::string> text = read_wisdom(path, failure, missing);
  if (!text) {
    set_problem(problem, std::move(failure));
    return false;
  }
  return fft::import_fft_wisdom_text(*text, fmt::format("wisdom file '{}'", path.string()), problem);
}

bool export_fft_wisdom(const fs::path& path, std::string* problem) {
  const std::string wisdom = fft::export_fft_wisdom_text();
  std::string failure = "FFTW could not export its wisdom";
  const bool written = !wisdom.empty() && write_wisdom(path, wisdom, failure);
  if (!written) set_problem(problem, std::move(failure));
  return written;
}

}  // namespace halfspace::io
