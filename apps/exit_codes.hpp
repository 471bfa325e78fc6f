// Exit codes of the `halfspace` program (documented in docs/usage.md).
#pragma once

namespace halfspace::app {

inline constexpr int kExitOk = 0;            // solved and converged, or --help / --version
inline constexpr int kExitInputError = 1;    // bad command line, config, input or output file
inline constexpr int kExitNotConverged = 2;  // solved without converging; the result is still written
inline constexpr int kExitPlotFailed = 3;    // solved and written, but --plot could not draw the figures

}  // namespace halfspace::app
