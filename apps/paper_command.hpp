// `halfspace paper`: reproduces Table 1 of the seed paper with Lemke, LCPquad
// and Polonsky-Keer, writes testN.csv, testN.h5, summary.md and the figures
// (drawn by scripts/halfspace_plot.py).
#pragma once

#include "command.hpp"

namespace halfspace::app {

// Registers `paper` on the program's parser.
Command add_paper_command(CLI::App& program);

}  // namespace halfspace::app
