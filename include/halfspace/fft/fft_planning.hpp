// How much effort FFTW spends choosing an algorithm when a plan is made.
#pragma once

#include <string_view>

namespace halfspace::fft {

enum class FftPlanning {
  estimate,  // FFTW_ESTIMATE: instant, a reasonable plan
  measure,   // FFTW_MEASURE: times candidate algorithms once
  patient,   // FFTW_PATIENT: times many more candidates
};

std::string_view to_string(FftPlanning planning);
// Parses "estimate", "measure" or "patient"; throws InputError otherwise.
FftPlanning parse_fft_planning(std::string_view text);

}  // namespace halfspace::fft

// The library and its front ends name these without the folder's namespace.
namespace halfspace {
using fft::FftPlanning;
using fft::parse_fft_planning;
using fft::to_string;
}  // namespace halfspace
