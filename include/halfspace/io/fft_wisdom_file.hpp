// FFTW wisdom in a file: where it lives, reading it, writing it like every
// output (output_file.hpp), and the store (fft/fft_wisdom.hpp) the front
// ends install so that measured plans use it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace halfspace::io {

// The wisdom file measured planning reads and writes:
//   $HALFSPACE_FFTW_WISDOM if set ("" or "off": no wisdom file, nullopt);
//   else $XDG_CACHE_HOME/halfspace/fftw-wisdom if XDG_CACHE_HOME is absolute;
//   else $HOME/.cache/halfspace/fftw-wisdom; nullopt if HOME is unset too.
// Single-precision plans (SingleRealFft) keep theirs in the same path with
// "-single" appended (FFTW holds the two precisions' wisdom apart).
std::optional<std::filesystem::path> fft_wisdom_path();

// Installs the file fft_wisdom_path() names (if any) as the wisdom store of
// this process's measured plans (fft::set_fft_wisdom_store).
void use_fft_wisdom_file();

// Merges the wisdom in `path` into FFTW's. Returns false, and says why in
// *problem if given, when the file is missing, unreadable, larger than
// 16 MiB, or not wisdom of this FFTW build (FFTW then keeps what it had).
bool import_fft_wisdom(const std::filesystem::path& path, std::string* problem = nullptr);

// Writes all of FFTW's wisdom to `path`, creating its directory: under a
// temporary name in the same directory, then renamed, so that concurrent
// runs and crashes never leave a partial file. Returns false, and says why
// in *problem if given, when it cannot be written.
bool export_fft_wisdom(const std::filesystem::path& path, std::string* problem = nullptr);

}  // namespace halfspace::io
