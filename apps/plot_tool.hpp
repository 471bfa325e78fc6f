// Finding and running the project's plotting tool (scripts/halfspace_plot.py,
// a matplotlib script) from the program, for `halfspace solve --plot`.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace halfspace::app {

// How long the tool may run before it is stopped, unless HALFSPACE_PLOT_TIMEOUT
// (seconds; 0 for no limit) says otherwise: a tool that never exits (a
// display it waits for, a locked font cache) must not hang the program.
inline constexpr double kDefaultPlotTimeoutSeconds = 120.0;

struct PlotTool {
  std::vector<std::string> interpreter;  // e.g. {"/usr/bin/python3"} or {"/usr/bin/env", "python3"}
  std::filesystem::path script;
  double timeout_seconds = kDefaultPlotTimeoutSeconds;  // 0: no limit
};

// Who asks for the tool, so that messages name the option and how to do
// without it: {"--plot", "drop --plot"} or {"halfspace paper", "use --no-figures"}.
struct PlotRequest {
  std::string_view by;
  std::string_view skip_hint;
  std::filesystem::path script;  // explicit path (e.g. --plot-script), else searched
};

// The tool, looked for in order: request.script; $HALFSPACE_PLOT_TOOL; the installed copy
// <prefix>/share/halfspace/halfspace_plot.py beside the program; the source
// tree the program was built from. Its interpreter is $HALFSPACE_PYTHON, else
// the script's #! line, else python3. Checks that the interpreter runs and
// imports matplotlib, h5py and numpy, so that a missing package is reported
// before a long solve. Throws InputError with a message saying what is
// missing and how to install it, or that HALFSPACE_PLOT_TIMEOUT is not a
// number of seconds.
PlotTool find_plot_tool(const PlotRequest& request);

// Runs `tool subcommand file` (the figures go next to `file`) in a process
// group of its own, its standard output suppressed when `quiet`; stops the
// group, the tool and any process it started (SIGTERM, then SIGKILL 5 s later
// or as soon as the tool has exited), once it has run tool.timeout_seconds. Returns an empty string on success,
// else one line saying what failed.
std::string run_plot_tool(const PlotTool& tool, std::string_view subcommand, const std::filesystem::path& file,
                          bool quiet);

}  // namespace halfspace::app
