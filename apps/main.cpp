// Entry point of the `halfspace` program: `--version`, `--help` and the
// subcommands. Every error ends here as one "error: ..." line on stderr.
#include <fmt/format.h>
#include <malloc.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "activity.hpp"
#include "command.hpp"
#include "exit_codes.hpp"
#include "generate_command.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/fft_wisdom_file.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/openmp_waiting.hpp"
#include "halfspace/version.hpp"
#include "lubricate_command.hpp"
#include "paper_command.hpp"
#include "processes.hpp"
#include "solve_command.hpp"
#include "stress_command.hpp"

int main(int argc, char** argv) {
  // First: it may start the program again, with OMP_WAIT_POLICY=passive.
  halfspace::use_passive_openmp_waiting(argv);
  // MPI's setup, in an MPI build, before anything else reads argv.
  const halfspace::app::Processes processes(argc, argv);
  const bool prints = halfspace::app::prints_messages();
  using halfspace::app::kExitInputError;
  // Field arrays (1 MiB and up) always come from mmap and go back to the
  // system when freed. glibc's default threshold rises after each such free,
  // after which same-sized arrays (pk-multilevel's coarse grids, the result
  // writer's buffers) land in the heap and stay resident: 9 bytes per grid
  // point more peak memory for pk-multilevel at 2048^2.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  // Ctrl-C or a kill while an output is being written removes its temporary
  // file (docs/usage.md#output-files).
  halfspace::io::install_output_cleanup_on_signals();
  // Measured plans keep their wisdom in the user's cache (docs/usage.md#fftw-wisdom).
  halfspace::io::use_fft_wisdom_file();
  CLI::App app{
      "halfspace: elastic contact of rough surfaces: normal, adhesive and frictional contact, subsurface stresses, "
      "lubricated (Reynolds, EHL and mixed) films",
      "halfspace"};
  app.set_version_flag("--version", fmt::format("halfspace {} ({})", halfspace::kVersion, halfspace::kGitHash));
  app.footer("Exit codes: 0 converged, 1 bad input or file error, 2 solved but not converged, 3 --plot failed.");
  app.require_subcommand(0, 1);

  // One line per subcommand.
  std::vector<halfspace::app::Command> commands;
  commands.push_back(halfspace::app::add_solve_command(app));
  commands.push_back(halfspace::app::add_generate_command(app));
  commands.push_back(halfspace::app::add_paper_command(app));
  commands.push_back(halfspace::app::add_stress_command(app));
  commands.push_back(halfspace::app::add_lubricate_command(app));

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);  // --help or --version: printed to stdout, exit 0
  } catch (const CLI::ParseError& error) {
    if (prints) fmt::print(stderr, "error: {} (see halfspace --help)\n", error.what());
    return kExitInputError;
  }

  for (const auto& command : commands) {
    if (!command.parser->parsed()) continue;
    try {
      // Only solve, generate, stress and lubricate are distributed; the paper's four
      // small line contacts are computed by the first process alone, the
      // others waiting; several processes of another command would write
      // one file side by side.
      const std::string& name = command.parser->get_name();
      const std::vector<std::string> arguments(argv, argv + argc);
      if (name == "paper") return halfspace::app::run_on_first_process([&] { return command.run(arguments); });
      if (halfspace::app::process_count() > 1 && name != "solve" && name != "generate" && name != "stress" &&
          name != "lubricate") {
        throw halfspace::InputError(
            fmt::format("{} is not available with more than one process: run it without mpirun (solve, generate, "
                        "stress, lubricate and paper are)",
                        name));
      }
      return command.run(arguments);
    } catch (const halfspace::InputError& error) {
      if (prints) fmt::print(stderr, "error: {}\n", error.what());
    } catch (const std::bad_alloc&) {
      // The estimate checked before the run (docs/usage.md#memory) did not
      // foresee it: other processes took the memory meanwhile, or the limit
      // was raised with --max-memory.
      const std::optional<halfspace::AvailableMemory> available = halfspace::available_memory();
      if (prints)
        fmt::print(stderr, "error: out of memory while {} ({} available now): use a smaller grid or free memory\n",
                   halfspace::app::Activity::failed_while(),
                   available ? halfspace::format_bytes(available->bytes) : std::string("unknown"));
    } catch (const std::exception& error) {
      // Not an input mistake we foresaw; still one line, still a failure.
      if (prints) fmt::print(stderr, "error: {} (while {})\n", error.what(), halfspace::app::Activity::failed_while());
    }
    return kExitInputError;
  }
  if (prints) fmt::print(stderr, "error: no command given: try 'halfspace --help'\n");
  return kExitInputError;
}
