// FFTW wisdom between runs: the load-once, save-when-grown handling that
// RealFft's measured planning calls under the planner lock, on the store a
// front end installed (the planning itself knows no files).
//
// Why failures are silent. Wisdom is a cache of planner timings: missing,
// unreadable or corrupt wisdom costs only the planning time that wisdom would
// have saved, never the accuracy of a transform, and the next measured plan
// replaces bad wisdom with good. So the library neither throws nor prints;
// fft_wisdom_status() keeps the reason for a front end that wants it.
#include "halfspace/fft/fft_wisdom.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <cstdlib>
#include <memory>
#include <utility>

#include "fftw_planner.hpp"

namespace halfspace::fft {
namespace {

// The automatic handling's state; guarded by the planner lock.
struct WisdomState {
  bool resolved = false;  // the store was asked for its wisdom (or there is none)
  std::optional<std::filesystem::path> path;
  bool loaded = false;
  bool saved = false;
  std::string problem;
  std::string known;  // FFTW's wisdom when last loaded or saved
};

// One state per precision: FFTW keeps double (fftw_) and single (fftwf_)
// wisdom apart, and so does the store.
WisdomState& wisdom_state(bool single = false) {
  static WisdomState states[2];
  return states[single ? 1 : 0];
}

// The installed store; guarded by the planner lock.
std::shared_ptr<const FftWisdomStore>& installed_store() {
  static std::shared_ptr<const FftWisdomStore> store;
  return store;
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
bool import_locked(const std::string& wisdom, std::string_view source, std::string* problem, bool single = false) {
  try {
    detail::init_fftw_threads();
  } catch (const std::exception& failure) {
    if (problem != nullptr) *problem = failure.what();
    return false;
  }
  // An embedded NUL would hide the rest of the text from FFTW's C-string
  // parser, which could then accept a truncated prefix.
  const int imported =
      single ? fftwf_import_wisdom_from_string(wisdom.c_str()) : fftw_import_wisdom_from_string(wisdom.c_str());
  if (wisdom.find('\0') != std::string::npos || imported == 0) {
    if (problem != nullptr) {
      *problem =
          fmt::format("{} is not wisdom of this FFTW build (corrupt, or written by another FFTW version)", source);
    }
    return false;
  }
  return true;
}

// The lock held: the store's wisdom merged into FFTW's. False with `problem`
// if it could not be read or was rejected; false with `problem` empty if the
// store has none yet.
bool load_locked(const FftWisdomStore& store, bool single, std::string& problem) {
  const std::optional<std::string> text = store.load(single, problem);
  return text &&
         import_locked(*text, fmt::format("wisdom file '{}'", store.location(single).string()), &problem, single);
}

}  // namespace

void set_fft_wisdom_store(std::shared_ptr<const FftWisdomStore> store) {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  installed_store() = std::move(store);
  for (const bool single : {false, true}) wisdom_state(single) = {};
}

FftWisdomStatus fft_wisdom_status() {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  const WisdomState& state = wisdom_state();
  return {state.path, state.loaded, state.saved, state.problem};
}

bool import_fft_wisdom_text(const std::string& text, std::string_view source, std::string* problem) {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  return import_locked(text, source, problem);
}

std::string export_fft_wisdom_text() {
  const std::lock_guard<std::mutex> lock(detail::fftw_planner_mutex());
  return exported_wisdom();
}

namespace detail {

void before_planning(FftPlanning planning, bool single) noexcept {
  if (planning == FftPlanning::estimate) return;
  WisdomState& state = wisdom_state(single);
  if (state.resolved) return;
  try {
    state.resolved = true;
    const std::shared_ptr<const FftWisdomStore>& store = installed_store();
    if (!store) return;
    state.path = store->location(single);
    std::string problem;
    state.loaded = load_locked(*store, single, problem);
    // No wisdom yet is the normal first run, not a problem.
    if (!state.loaded && !problem.empty()) state.problem = std::move(problem);
    state.known = exported_wisdom(single);
  } catch (...) {
    state.problem = "the wisdom file could not be loaded (out of memory)";
  }
}

void after_planning(FftPlanning planning, bool single) noexcept {
  if (planning == FftPlanning::estimate) return;
  WisdomState& state = wisdom_state(single);
  const std::shared_ptr<const FftWisdomStore>& store = installed_store();
  if (!state.path || !store) return;
  try {
    if (exported_wisdom(single) == state.known) return;
    // Merge what other runs saved since this one loaded the store, so that
    // concurrent runs do not drop each other's wisdom; wisdom that fails to
    // read now is simply replaced.
    std::string problem;
    load_locked(*store, single, problem);
    problem.clear();
    const std::string wisdom = exported_wisdom(single);
    if (wisdom.empty()) {
      state.problem = "FFTW could not export its wisdom";
    } else if (store->save(single, wisdom, problem)) {
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
