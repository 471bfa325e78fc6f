// FFTW wisdom kept between runs: the timings behind measured plans, so that
// the next run plans the same sizes at once. The planning knows no files: a
// front end installs a store (io/fft_wisdom_file.hpp's file in the user's
// cache), and RealFft then loads it once, before its first measure or
// patient plan, and saves FFTW's wisdom back (merged with the store's current
// contents) after any such plan that added to it. Without a store, measured
// plans start from scratch in every process.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace halfspace::fft {

// Where wisdom is kept, as text, for each precision (single: SingleRealFft's;
// FFTW holds the two precisions' wisdom apart). Called under FFTW's planner
// lock, so it must not plan or call the functions below.
class FftWisdomStore {
 public:
  virtual ~FftWisdomStore() = default;
  // Where the precision's wisdom lives (messages, fft_wisdom_status).
  virtual std::filesystem::path location(bool single) const = 0;
  // The stored text; nullopt if there is none yet (problem left empty: a
  // first run) or it cannot be read (problem says why).
  virtual std::optional<std::string> load(bool single, std::string& problem) const = 0;
  // Stores `text`; false, with problem saying why, if it cannot.
  virtual bool save(bool single, const std::string& text, std::string& problem) const = 0;
};

// Installs `store` for the measured plans that follow (nullptr: none).
void set_fft_wisdom_store(std::shared_ptr<const FftWisdomStore> store);

// What the automatic wisdom handling of this process did (for double
// precision). Failures never throw and never change a result: missing,
// unreadable or corrupt wisdom only means planning from scratch, and wisdom
// that cannot be stored only means planning again next time.
struct FftWisdomStatus {
  std::optional<std::filesystem::path> path;  // the store's location; nullopt if none or not used yet
  bool loaded = false;                        // its wisdom was read and accepted by FFTW
  bool saved = false;                         // new wisdom was stored
  std::string problem;                        // the last failure to read or store it; empty if none
};
FftWisdomStatus fft_wisdom_status();

// Merges `text` into FFTW's wisdom. Returns false, and says why in *problem
// if given (naming `source`, e.g. "wisdom file 'x'"), when it is not wisdom of
// this FFTW build (FFTW then keeps what it had).
bool import_fft_wisdom_text(const std::string& text, std::string_view source, std::string* problem = nullptr);
// All of FFTW's double-precision wisdom as text; empty if it cannot be exported.
std::string export_fft_wisdom_text();

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::fft_wisdom_status;
using fft::FftWisdomStatus;
}  // namespace halfspace
