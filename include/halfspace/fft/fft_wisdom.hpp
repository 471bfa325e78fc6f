// FFTW wisdom kept between runs: the timings behind measured plans, saved in
// the user's cache directory so that the next run plans the same sizes at
// once. RealFft uses it by itself for FftPlanning::measure and patient.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace halfspace::fft {

// The wisdom file measured planning reads and writes:
//   $HALFSPACE_FFTW_WISDOM if set ("" or "off": no wisdom file, nullopt);
//   else $XDG_CACHE_HOME/halfspace/fftw-wisdom if XDG_CACHE_HOME is absolute;
//   else $HOME/.cache/halfspace/fftw-wisdom; nullopt if HOME is unset too.
// Single-precision plans (SingleRealFft) keep theirs in the same path with
// "-single" appended (FFTW holds the two precisions' wisdom apart).
std::optional<std::filesystem::path> fft_wisdom_path();

// What the automatic wisdom handling of this process did (for the
// double-precision file). RealFft loads the
// file once, before its first measure or patient plan, and saves FFTW's
// wisdom back (merged with the file's current contents) after any such plan
// that added to it. Failures never throw and never change a result: a
// missing, unreadable or corrupt file only means planning from scratch, and
// a file that cannot be written only means planning again next time.
struct FftWisdomStatus {
  std::optional<std::filesystem::path> path;  // the file in use; nullopt if off or not used yet
  bool loaded = false;                        // the file was read and accepted by FFTW
  bool saved = false;                         // new wisdom was written to it
  std::string problem;                        // the last failure to read or write it; empty if none
};
FftWisdomStatus fft_wisdom_status();

// Merges the wisdom in `path` into FFTW's. Returns false, and says why in
// *problem if given, when the file is missing, unreadable, larger than
// 16 MiB, or not wisdom of this FFTW build (FFTW then keeps what it had).
bool import_fft_wisdom(const std::filesystem::path& path, std::string* problem = nullptr);

// Writes all of FFTW's wisdom to `path`, creating its directory: under a
// temporary name in the same directory, then renamed, so that concurrent
// runs and crashes never leave a partial file. Returns false, and says why
// in *problem if given, when it cannot be written.
bool export_fft_wisdom(const std::filesystem::path& path, std::string* problem = nullptr);

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::export_fft_wisdom;
using fft::fft_wisdom_path;
using fft::fft_wisdom_status;
using fft::FftWisdomStatus;
using fft::import_fft_wisdom;
}  // namespace halfspace
