// Every test runs with FFTW wisdom off, so that no test (and no `halfspace`
// run it starts, which inherits the environment) reads or writes the user's
// cache directory; the wisdom tests pass their own file. Set before main, and
// FFTW's wisdom is consulted only at the first measured plan.
#include <cstdlib>

namespace {

const bool kWisdomOff = ::setenv("HALFSPACE_FFTW_WISDOM", "off", 1) == 0;

}  // namespace
