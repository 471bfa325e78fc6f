// FFTW wisdom between runs: where the file lives, reading it (any failure
// ignored), writing it atomically, and the load-once, save-when-grown
// handling that RealFft's measured planning calls under the planner lock.
//
// Why failures are silent. Wisdom is a cache of planner timings: a missing,
// unreadable or corrupt file costs only the planning time that wisdom would
// have saved, never the accuracy of a transform, and the next measured plan
// replaces a bad file with good wisdom. So the library neither throws nor
// prints; fft_wisdom_status() keeps the reason for a front end that wants it.
#include "halfspace/fft/fft_wisdom.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include "fftw_planner.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/output_file.hpp"

namespace halfspace::fft {
namespace {

namespace fs = std::filesystem;

// Wisdom for a handful of sizes is a few kilobytes; a file this large is not
// wisdom, and is not read into memory.
constexpr std::uintmax_t kMaxWisdomBytes = std::uintmax_t{16} << 20;

// The automatic handling's state; guarded by the planner lock.
struct WisdomState {
  bool resolved = false;  // the path was looked up and the file read (or not)
  std::optional<fs::path> path;
  bool loaded = false;
  bool saved = false;
  std::string problem;
  std::string known;  // FFTW's wisdom when last loaded or saved
};

// One state per precision: FFTW keeps double (fftw_) and single (fftwf_)
// wisdom apart, and so do the files.
WisdomState& wisdom_state(bool single = false) {
  static WisdomState states[2];
  return states[single ? 1 : 0];
}

// The single-precision plans' file beside the double ones'.
fs::path single_precision_path(const fs::path& path) {
  fs::path single = path;
  single += "-single";
  return single;
}

enum class ReadOutcome { loaded, missing, failed };

void set_problem(std::string* problem, std::string text) {
  if (problem != nullptr) *problem = std::move(text);
}

// FFTW's accumulated wisdom as text; empty if it cannot be exported. FFTW
// allocates the string with malloc (FFTW 3.3 manual, section 4.7.2).
std::string exported_wisdom(bool single = false) {
  const std::unique_ptr<char, decltype(&std::free)> text(
      single ? fftwf_export_wisdom_to_string() : fftw_export_wisdom_to_string(), &std::free);
  return text ? std::string(text.get()) : std::string();
}

// The lock held. FFTW rejects text that is not its wisdom, or wisdom of
// another FFTW version or build, as a whole and keeps what it had.
ReadOutcome import_locked(const fs::path& path, std::string* problem, bool single = false) {
  const std::string shown = path.string();
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) {
    set_problem(problem, fmt::format("wisdom file '{}' does not exist", shown));
    return ReadOutcome::missing;
  }
  if (!fs::is_regular_file(status)) {
    set_problem(problem, fmt::format("wisdom file '{}' is not a regular file", shown));
    return ReadOutcome::failed;
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error || size > kMaxWisdomBytes) {
    set_problem(problem, fmt::format("wisdom file '{}' is larger than {} bytes", shown, kMaxWisdomBytes));
    return ReadOutcome::failed;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) {
    set_problem(problem, fmt::format("wisdom file '{}' cannot be read", shown));
    return ReadOutcome::failed;
  }
  const std::string wisdom = text.str();
  try {
    detail::init_fftw_threads();
  } catch (const std::exception& failure) {
    set_problem(problem, failure.what());
    return ReadOutcome::failed;
  }
  // An embedded NUL would hide the rest of the file from FFTW's C-string
  // parser, which could then accept a truncated prefix.
  const int imported =
      single ? fftwf_import_wisdom_from_string(wisdom.c_str()) : fftw_import_wisdom_from_string(wisdom.c_str());
  if (wisdom.find('\0') != std::string::npos || imported == 0) {
    set_problem(problem, fmt::format("wisdom file '{}' is not wisdom of this FFTW build (corrupt, or written by "
                                     "another FFTW version)",
                                     shown));
    return ReadOutcome::failed;
  }
  return ReadOutcome::loaded;
}

// The lock held. Written like every output (io/output_file.hpp): under a
// temporary name and renamed, so runs side by side never see a partial file,
// and never onto a device, FIFO or directory.
bool export_locked(const fs::path& path, std::string* problem, bool single = false) {
  const std::string wisdom = exported_wisdom(single);
  if (wisdom.empty()) {
    set_problem(problem, "FFTW could not export its wisdom");
    return false;
  }
  std::error_code error;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), error);
    if (error) {
      set_problem(problem, fmt::format("cannot create directory '{}' for the wisdom file: {}",
                                       path.parent_path().string(), error.message()));
      return false;
    }
  }
  try {
    io::write_output_file(path, wisdom);
  } catch (const FileError& failure) {
    set_problem(problem, fmt::format("wisdom not saved: {}", failure.what()));
    return false;
  }
  return true;
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

FftWisdomStatus fft_wisdom_status() {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  const WisdomState& state = wisdom_state();
  return {state.path, state.loaded, state.saved, state.problem};
}

bool import_fft_wisdom(const fs::path& path, std::string* problem) {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  return import_locked(path, problem) == ReadOutcome::loaded;
}

bool export_fft_wisdom(const fs::path& path, std::string* problem) {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  return export_locked(path, problem);
}

namespace detail {

void before_planning(FftPlanning planning, bool single) noexcept {
  if (planning == FftPlanning::estimate) return;
  WisdomState& state = wisdom_state(single);
  if (state.resolved) return;
  try {
    state.resolved = true;
    state.path = fft_wisdom_path();
    if (!state.path) return;
    if (single) state.path = single_precision_path(*state.path);
    std::string problem;
    const ReadOutcome outcome = import_locked(*state.path, &problem, single);
    state.loaded = outcome == ReadOutcome::loaded;
    // A missing file is the normal first run, not a problem.
    if (outcome == ReadOutcome::failed) state.problem = std::move(problem);
    state.known = exported_wisdom(single);
  } catch (...) {
    state.problem = "the wisdom file could not be loaded (out of memory)";
  }
}

void after_planning(FftPlanning planning, bool single) noexcept {
  if (planning == FftPlanning::estimate) return;
  WisdomState& state = wisdom_state(single);
  if (!state.path) return;
  try {
    if (exported_wisdom(single) == state.known) return;
    // Merge what other runs saved since this one loaded the file, so that
    // concurrent runs do not drop each other's wisdom; a file that fails to
    // read now is simply replaced.
    import_locked(*state.path, nullptr, single);
    std::string problem;
    if (export_locked(*state.path, &problem, single)) {
      state.saved = true;
    } else {
      state.problem = std::move(problem);
    }
    // Also after a failed save: retrying at every plan would not help.
    state.known = exported_wisdom(single);
  } catch (...) {
    state.problem = "the wisdom file could not be saved (out of memory)";
  }
}

}  // namespace detail
}  // namespace halfspace::fft
