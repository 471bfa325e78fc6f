// FFT planning names: round trip and the error for an unknown name.
#include "halfspace/fft/fft_planning.hpp"

#include <gtest/gtest.h>

#include <string>

#include "halfspace/error.hpp"

namespace halfspace {
namespace {

TEST(FftPlanningTest, NamesRoundTrip) {
  for (const FftPlanning planning : {FftPlanning::estimate, FftPlanning::measure, FftPlanning::patient}) {
    EXPECT_EQ(parse_fft_planning(to_string(planning)), planning);
  }
  EXPECT_EQ(to_string(FftPlanning::measure), "measure");
}

TEST(FftPlanningTest, RejectsUnknownNameWithMessage) {
  try {
    parse_fft_planning("exhaustive");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'exhaustive'"), std::string::npos) << message;
    for (const char* allowed : {"estimate", "measure", "patient"}) {
      EXPECT_NE(message.find(allowed), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace halfspace
