// How much memory a run will need, worked out from the grid before anything
// is allocated, and how much the machine has, so that a request far beyond
// it is refused with a message instead of ending in std::bad_alloc, the
// out-of-memory killer or minutes of swapping.
//
// The estimates add up the arrays each part allocates (operator, FFT buffers,
// solver workspace, result fields, the file image the writer builds) at the
// peak of each phase of the run. They are upper bounds: the measured peak
// (maximum resident set size) stays below them, and above a third of them
// (tests/memory_estimate_test.cpp).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "halfspace/grid.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace {

// What the halfspace program holds before a run allocates anything: code,
// libraries, FFTW's and HDF5's own state (measured: 27-30 MiB).
inline constexpr double kProgramBytes = 40.0 * 1024 * 1024;

// Peak bytes of `halfspace solve` on `grid` with `settings` (solver, maximum
// iterations, deflation) and `load_steps` loads (more than one: a sweep,
// which keeps every step's fields): kProgramBytes, the heights and the
// initial gap, and the largest of the solve (the coarse-grid start of
// pk-multilevel, the fine solve) and the writing of the result file.
// `gap_in_heights`: a single solve whose initial gap takes the heights'
// place (solvers::solve_surface_in_place, where
// solvers::initial_gap_in_heights holds), one field less while it solves.
// Bytes are doubles: the count for a grid of 2^32 x 2^32 cells does not fit
// in std::size_t.
double solve_memory_estimate(const Grid& grid, const solvers::SolverOptions& settings, std::size_t load_steps = 1,
                             bool gap_in_heights = false);

// Peak bytes of one process of a distributed solve (the MPI program) on
// `grid` when it holds `rows` of its rows: kProgramBytes and its share of
// the heights, the initial gap and the solve (the slab transform and
// symbols, the workspace and the result; block deflation's contact flags
// and lists, which every process holds for the whole grid). With
// `load_steps` > 1 (a sweep) also its rows of every finished step's fields
// and every step's cluster sizes, kept until the collective writing. The
// statistics and the collective writing work on the same fields in place,
// with less besides (the slab transform of the slope, the cluster labels);
// no file image is assembled.
double slab_solve_memory_estimate(const Grid& grid, const solvers::SolverOptions& settings, std::size_t rows,
                                  std::size_t load_steps = 1);

// Peak bytes while a solve's stresses are computed and written after it, at
// `depth_count` depths (0: none asked, 0 bytes): kProgramBytes, the heights
// and the result's fields (6 arrays) kept, the stress transforms and one
// depth's fields (the depths go one at a time). `shear`: the result has shear
// tractions (friction); `body1_tractions`: the stressed body is body 1, which
// takes their negatives in two arrays of its own (stress::tractions_on).
double solve_stress_memory_estimate(const Grid& grid, std::size_t depth_count, bool coated, bool shear,
                                    bool body1_tractions);

// Peak bytes of `halfspace stress` on a result of `grid`: kProgramBytes and,
// of the cells this process holds (`share` of the grid: 1 on one process),
// the tractions read twice (the reader's copy and the field), body 1's
// negated shear and the stress transforms with one depth's fields.
double stress_command_memory_estimate(const Grid& grid, bool coated, bool shear, double share = 1.0);

// Peak bytes of `halfspace generate` on `grid`: kProgramBytes, the
// synthesis transform of a self-affine surface and the heights (the
// deterministic shapes need less).
double generate_memory_estimate(const Grid& grid);

// The memory this process may still use, and where that figure comes from.
struct AvailableMemory {
  double bytes = 0.0;
  std::string source;  // e.g. "MemAvailable in /proc/meminfo"
};

// The smallest of MemAvailable (/proc/meminfo) and, where a cgroup limits
// this process's memory, that limit less the cgroup's usage (page cache it
// can reclaim excepted): cgroup v2 memory.max along the process's cgroup
// path, or v1 memory.limit_in_bytes. Nothing if none can be read.
// `proc` and `cgroup` are the mount points, replaceable for tests.
std::optional<AvailableMemory> available_memory(const std::filesystem::path& proc = "/proc",
                                                const std::filesystem::path& cgroup = "/sys/fs/cgroup");

// "512 MiB", "1.5 GiB", "93.1 TiB": three significant digits, binary units.
std::string format_bytes(double bytes);

}  // namespace halfspace
