// The Table 1 reproduction as a command: runs the tests, writes the data
// files and the summary, prints one line per test and has the figures drawn
// by the project's plotting tool (a Python script run as a child process).
#include "paper_command.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/paper/paper_output.hpp"
#include "halfspace/paper/reproduction.hpp"
#include "halfspace/threads.hpp"
#include "plot_tool.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

namespace fs = std::filesystem;

struct PaperOptions {
  std::optional<int> test;  // all four when not given
  double load = paper::kDefaultLoad;
  std::string output_dir;
  bool unscaled_qp = false;
  bool point_load_kernel = false;
  bool no_figures = false;
  std::string plot_script;
  bool quiet = false;
};

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw FileError(fmt::format("cannot write output '{}'", path.string()));
}

int run_paper(const PaperOptions& options) {
  paper::ReproductionOptions reproduction;
  reproduction.load = options.load;
  reproduction.unscaled_qp = options.unscaled_qp;
  reproduction.point_load_kernel = options.point_load_kernel;
  reproduction.validate();
  // At most 500 cells: one thread is fastest, and keeps the times steady on
  // a busy machine.
  set_threads(1);
  std::vector<int> numbers{1, 2, 3, 4};
  if (options.test) numbers = {paper::table1_test(*options.test).number};
  const std::optional<PlotTool> plot =
      options.no_figures
          ? std::nullopt
          : std::optional<PlotTool>(find_plot_tool({"halfspace paper", "use --no-figures", options.plot_script}));

  const fs::path directory = options.output_dir;
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
  auto options = std::make_shared<PaperOptions>();
  command->add_option("--test", options->test, "run only test N of Table 1 (1 to 4) [all]")
      ->type_name("N")
      ->check(CLI::Range(1, 4));
  command->add_option("--load", options->load, "line load W (N/m per unit length) [1e5]")->type_name("W");
  command->add_option("--output-dir", options->output_dir, "directory for the files; created if missing")
      ->type_name("DIR")
      ->required();
  command->add_flag("--unscaled-qp", options->unscaled_qp,
                    "also solve LCPquad in SI units, without nondimensionalisation (columns p_lcpquad_si, "
                    "p_lcpquad_si_approach)");
  command->add_flag("--point-load-kernel", options->point_load_kernel,
                    "also solve with the paper's eq. (4) kernel by Lemke (column p_lemke_eq4)");
  command->add_flag("--no-figures", options->no_figures, "write the data files only");
  command->add_option("--plot-script", options->plot_script, "the plotting tool [found automatically]")
      ->type_name("FILE");
  command->add_flag("--quiet", options->quiet, "print nothing unless there is an error");
  return {command, [options](const std::vector<std::string>& /*argv*/) { return run_paper(*options); }};
}

}  // namespace halfspace::app
