// The Table 1 reproduction as a command: runs the tests, writes the data
// files and the summary, prints one line per test and has the figures drawn
// by the project's plotting tool (a Python script run as a child process).
#include "paper_command.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/paper/paper_output.hpp"
#include "halfspace/paper/reproduction.hpp"
#include "halfspace/threads.hpp"
#include "option_table.hpp"
#include "plot_tool.hpp"

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

// Everything `halfspace paper` accepts; an empty optional was not given.
struct PaperOptions : GivenOptions {
  std::optional<long long> test;  // all four when not given
  std::optional<double> load;     // paper::kDefaultLoad when not given
  std::optional<std::string> output_dir;
  bool unscaled_qp = false;
  bool point_load_kernel = false;
  bool no_figures = false;
  std::optional<std::string> plot_script;
  bool quiet = false;
};

using PaperOption = OptionSpec<PaperOptions>;
using Kind = OptionKind;

constexpr std::string_view kRun = "Run";
constexpr std::string_view kOutput = "Output";

const std::array kOptions{
    PaperOption{"test", &PaperOptions::test, Kind::integer, kRun, "N", "run only test N of Table 1 (1 to 4) [all]"},
    PaperOption{"load", &PaperOptions::load, Kind::number, kRun, "W", "line load W (N/m per unit length) [1e5]"},
    PaperOption{"unscaled-qp", &PaperOptions::unscaled_qp, Kind::flag, kRun, "",
                "also solve LCPquad in SI units, without nondimensionalisation (columns p_lcpquad_si, "
                "p_lcpquad_si_approach)"},
    PaperOption{"point-load-kernel", &PaperOptions::point_load_kernel, Kind::flag, kRun, "",
                "also solve with the paper's eq. (4) kernel by Lemke (column p_lemke_eq4)"},
    PaperOption{"output-dir", &PaperOptions::output_dir, Kind::path, kOutput, "DIR",
                "directory for the files; created if missing (required)"},
    PaperOption{"no-figures", &PaperOptions::no_figures, Kind::flag, kOutput, "", "write the data files only"},
    PaperOption{"plot-script", &PaperOptions::plot_script, Kind::path, kOutput, "FILE",
                "the plotting tool [found automatically]"},
    PaperOption{"quiet", &PaperOptions::quiet, Kind::flag, kOutput, "", "print nothing unless there is an error"},
};

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw FileError(fmt::format("cannot write output '{}'", path.string()));
}

int run_paper(const PaperOptions& options) {
  if (!options.output_dir) throw InputError("--output-dir is required: the directory for the files");
  paper::ReproductionOptions reproduction;
  reproduction.load = options.load.value_or(paper::kDefaultLoad);
  reproduction.unscaled_qp = options.unscaled_qp;
  reproduction.point_load_kernel = options.point_load_kernel;
  reproduction.validate();
  // At most 500 cells: one thread is fastest, and keeps the times steady on
  // a busy machine.
  set_threads(1);
  std::vector<int> numbers{1, 2, 3, 4};
  if (options.test) {
    numbers = {in_context(options.name("test"), [&] { return paper::table1_test(*options.test).number; })};
  }
  const std::optional<PlotTool> plot =
      options.no_figures ? std::nullopt
                         : std::optional<PlotTool>(find_plot_tool(
                               {"halfspace paper", "use --no-figures", options.plot_script.value_or("")}));

  const fs::path directory = *options.output_dir;
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory)) {
    throw FileError(fmt::format("cannot create output directory '{}': {}", directory.string(),
                                error ? error.message() : "a file of that name exists"));
  }

  std::vector<paper::TestReproduction> runs;
  bool converged = true;
  for (int number : numbers) {
    paper::TestReproduction run = paper::reproduce(paper::table1_test(number), reproduction);
    paper::write_csv(directory / fmt::format("test{}.csv", number), run);
    paper::write_hdf5(directory / fmt::format("test{}.h5", number), run, reproduction);
    if (!options.quiet) {
      fmt::print(
          "test {}: N = {:3}, contact nodes {:3}, max p/p_H {:.6f}; max |dp|/p_H Lemke-LCPquad {:.1e}, "
          "Lemke-PK {:.1e}, LCPquad-PK {:.1e}; {} pivots, {} IPM iterations, {} PK iterations\n",
          number, run.contact.test.nodes, paper::contact_nodes(run.lemke),
          run.lemke.max_pressure / run.contact.hertz.peak, run.lemke_vs_lcpquad, run.lemke_vs_pk, run.lcpquad_vs_pk,
          run.lemke_report.iterations, run.lcpquad_report.iterations, run.pk.iterations);
    }
    for (const SolveResult* result : {&run.lemke, &run.lcpquad, &run.pk}) {
      if (!result->converged()) {
        converged = false;
        fmt::print(stderr, "test {}: {} did not converge: {}\n", number, result->solver, result->message);
      }
    }
    runs.push_back(std::move(run));
  }
  write_text(directory / "summary.md", paper::summary_markdown(runs, reproduction));
  if (!options.quiet) fmt::print("wrote {}\n", (directory / "summary.md").string());
  std::fflush(stdout);  // before the plotting tool prints the figures it writes
  if (plot) {
    // The data files are written whatever happens to the figures.
    const std::string failure = run_plot_tool(*plot, "paper", directory, options.quiet);
    if (!failure.empty()) {
      fmt::print(stderr, "error: the figures could not be drawn: {}; the data files are written\n", failure);
      return converged ? kExitPlotFailed : kExitNotConverged;
    }
  }
  return converged ? kExitOk : kExitNotConverged;
}

}  // namespace

Command add_paper_command(CLI::App& program) {
  CLI::App* command = program.add_subcommand(
      "paper", "Reproduce Table 1 of the seed paper (Lemke, LCPquad and Polonsky-Keer on four line contacts)");
  command->footer(
      "Files: testN.csv, testN.h5, summary.md and the figures testN.png, testN_zoom.png; see docs/paper.md.");
  return {command, table_command(*command, std::span<const PaperOption>(kOptions), "load = 2e5", run_paper)};
}

}  // namespace halfspace::app
