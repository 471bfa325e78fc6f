// Where a solve runs and how its statistics and files are made: the whole
// grid on this process (serial_place), or this process's slab of rows
// (apps/mpi/mpi_program.cpp), every hook then collective. The normal and the
// frictional pipelines (solve_command.cpp, friction_command.cpp) run
// unchanged at either.
#pragma once

#include <functional>
#include <initializer_list>
#include <optional>
#include <span>

#include "halfspace/analysis/contact_statistics.hpp"
#include "halfspace/analysis/load_sweep.hpp"
#include "halfspace/io/result_metadata.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/solvers/solve_result.hpp"
#include "halfspace/solvers/tangential_loading.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "plot_tool.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

struct SolvePlace {
  const solvers::Layout& layout;
  std::span<double> heights;                       // the cells `layout` holds here (lent to a single solve)
  bool first = true;                               // the first (or only) process: it prints and plots
  int processes = 1;                               // how many share the grid
  std::function<io::ResultMetadata()> metadata{};  // provenance and surface statistics
  std::function<analysis::ContactStatistics(const SolveResult& normal)> contact_statistics{};
  std::function<void(const SolveResult& normal, const io::ResultMetadata& metadata)> write_result{};
  std::function<void(const SolveResult& normal, std::span<const TangentialResult> steps,
                     std::span<const TangentialLoading> loads, const io::ResultMetadata& metadata)>
      write_history{};
  // A load sweep's HDF5 file and its CSV table.
  std::function<void(std::span<const analysis::SweepStep> steps, const io::ResultMetadata& metadata)> write_sweep{};
  // Runs a step everywhere, every process learning of a failure on any;
  // the first process's value on every process (one process: the step, the
  // value).
  std::function<void(const std::function<void()>& step)> agree = [](const std::function<void()>& step) { step(); };
  std::function<int(int value)> first_value = [](int value) { return value; };
};

// The whole of setup's grid on this process.
SolvePlace serial_place(const SolveSetup& setup);

// The start of a solve at `place`: the threads set (the FFT plans use the
// thread count in force when made) and, with setup.plot, the plotting tool
// found by the first process, every process learning before the solve
// whether it is there.
std::optional<PlotTool> start_solve(const SolveSetup& setup, const SolvePlace& place);

// Draws `figures` from setup.output with `plot` (if found), stopping at the
// first that fails (its error printed, then `written`, e.g. "the result is
// written to"): whether every one was drawn.
bool draw_figures(const std::optional<PlotTool>& plot, std::initializer_list<std::string_view> figures,
                  const SolveSetup& setup, std::string_view written);

}  // namespace halfspace::app
