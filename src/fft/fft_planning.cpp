// Names of the FFTW planning levels, for configuration files and the CLI.
#include "halfspace/fft/fft_planning.hpp"

#include <fmt/format.h>

#include "halfspace/error.hpp"

namespace halfspace::fft {

std::string_view to_string(FftPlanning planning) {
  switch (planning) {
    case FftPlanning::estimate:
      return "estimate";
    case FftPlanning::measure:
      return "measure";
    case FftPlanning::patient:
      return "patient";
  }
  return "unknown";
}

FftPlanning parse_fft_planning(std::string_view text) {
  if (text == "estimate") return FftPlanning::estimate;
  if (text == "measure") return FftPlanning::measure;
  if (text == "patient") return FftPlanning::patient;
  throw InputError(fmt::format("FFT planning '{}' is not known: use 'estimate', 'measure' or 'patient'", text));
}

}  // namespace halfspace::fft
