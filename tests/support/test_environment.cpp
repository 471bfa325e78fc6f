// Every test, and every `halfspace` run a test starts (which inherits the
// environment), keeps its FFTW wisdom in the build tree, never in the user's
// cache directory: measured plans (the program's default) then cost their
// planning time once per grid size and build rather than in every test. The
// wisdom tests pass their own files. Set before main; FFTW's wisdom is
// consulted only at the first measured plan.
#include <cstdlib>

#include "halfspace/io/fft_wisdom_file.hpp"

namespace {

const bool kWisdomInBuildTree = ::setenv("HALFSPACE_FFTW_WISDOM", HALFSPACE_TEST_WISDOM_FILE, 1) == 0 &&
                                (halfspace::io::use_fft_wisdom_file(), true);

}  // namespace
