// Memory estimates from the sizes of the arrays each part of a run makes
// (docs/performance.md measures the same runs: 70-86 B per cell for periodic
// 2D solves, 100-120 for free ones), and the memory the machine has left.
#include "halfspace/memory_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "halfspace/io/result_writer.hpp"
#include "halfspace/stress/stress_volume.hpp"

namespace halfspace {
namespace {

namespace fs = std::filesystem;

constexpr double kDouble = 8.0;
constexpr double kFloat = 4.0;
constexpr double kComplex = 16.0;

// A grid's extents as doubles, so that no product of them can overflow.
struct Extents {
  double nx;
  double ny;  // 1 for a line
  bool line;
  bool periodic;
  double cells() const { return nx * ny; }

  explicit Extents(const Grid& grid)
      : nx(static_cast<double>(grid.nx())),
        ny(static_cast<double>(grid.ny())),
        line(grid.dimension() == 1),
        periodic(grid.periodic()) {}
  // pk-multilevel's next coarser grid: half the cells per axis.
  Extents coarser() const {
    Extents coarse = *this;
    coarse.nx = std::floor(nx / 2.0);
    if (!line) coarse.ny = std::floor(ny / 2.0);
    return coarse;
  }
};

// Rows an EvenSymbol of `rows` rows stores (even_symbol.hpp: folded in half).
double stored_rows(double rows) {
  const double half = std::floor(rows / 2.0) + 1.0;
  return half < rows ? half : rows;
}

// The operator u = K p (fft_influence_operator.cpp). Periodic: the grid's
// transform (its spectrum; the real arrays are the solver's) and the kernel
// symbol. Free: the zero-padded transform's spectrum (2 ny rows of nx + 1
// in 2D), a line's own real buffer, and the kernel symbol of the padded grid.
double operator_bytes(const Extents& g) {
  if (g.periodic) {
    const double rows = g.line ? 1.0 : g.ny;
    const double cols = std::floor(g.nx / 2.0) + 1.0;
    return kComplex * rows * cols + kDouble * stored_rows(rows) * cols;
  }
  const double rows = g.line ? 1.0 : 2.0 * g.ny;
  const double cols = g.nx + 1.0;
  return kComplex * rows * cols + (g.line ? kDouble * (2.0 * g.nx + 2.0) : 0.0) + kDouble * stored_rows(rows) * cols;
}

// The Fourier preconditioner: its symbol on a free grid, where its
// transform works in the operator's padded buffer. On a periodic grid it
// shares the operator's transform and inverts its symbol (layout.cpp).
double preconditioner_bytes(const Extents& g) {
  if (g.periodic) return 0.0;
  const double rows = g.line ? 1.0 : g.ny;
  return kDouble * stored_rows(rows) * (std::floor(g.nx / 2.0) + 1.0);
}

// The coarse-grid correction (block_deflation.hpp): its field (none on
// single-precision work vectors, whose products' scratch serves), the set's flags and three lists
// of 8-byte cells (current, previous, changed), each at most one entry per
// cell.
double deflation_bytes(const Extents& g, double field) {
  return (field + 1.0 + 3.0 * kDouble) * g.cells();
}

// The precision of Polonsky-Keer's work vectors: float with mixed
// precision on a periodic grid (layout.cpp's make_mixed_operators).
double work_bytes(const Extents& g, bool mixed) {
  return mixed && g.periodic ? kFloat : kDouble;
}

// One Polonsky-Keer solver with its operator, between solves: the
// operator, the preconditioner and the coarse correction (its field in
// double, or none on float work vectors). With mixed precision on a
// periodic grid the single-precision K shares the double one's symbol and
// its transform lives in the double one's spectrum, its real array the
// correction's field (balancing_preconditioner.cpp).
double level_bytes(const Extents& g, bool preconditioned, bool deflated, bool mixed) {
  const bool single_work = work_bytes(g, mixed) == kFloat;
  return operator_bytes(g) + (preconditioned ? preconditioner_bytes(g) : 0.0) +
         (deflated ? deflation_bytes(g, single_work ? 0.0 : kDouble) : 0.0);
}

// A solve's result: pressure, displacement and gap, and the residual history.
double result_bytes(const Extents& g, double history) {
  return 3.0 * kDouble * g.cells() + history;
}

// The fields of a Polonsky-Keer solve: the pressure and displacement, the
// two work vectors (the gap, not stored during the iteration, takes their
// place at the end: never more than they), the residual history reserved
// for the iteration limit; a byte per cell for the search set's mask
// (polonsky_keer.cpp); and a byte per cell for the active-set phase before
// it (active_set_start.cpp), whose displacement takes the place of the
// solve's and whose byte mask is the one field more.
double solve_bytes(const Extents& g, double history, bool mixed) {
  return (2.0 * kDouble + 2.0 * work_bytes(g, mixed) + 2.0) * g.cells() + history;
}

// The dense LCP solvers (lemke, lcpquad) on N <= kMaxDenseCells cells: the
// assembled N x N influence matrix, the scaled LCP matrix made from it and
// the solver's own copies and factors (Siconos' tableau, ALGLIB's dense
// quadratic term and its factorisation), five matrices in all.
double dense_bytes(const Extents& g) {
  const double n = g.cells();
  return 5.0 * kDouble * n * n;
}

bool is_dense(solvers::SolverType type) {
  return type == solvers::SolverType::lemke || type == solvers::SolverType::lcpquad;
}

// Whether the fine Polonsky-Keer solve holds the block deflation's fields.
bool deflated(const Grid& grid, const solvers::SolverOptions& options) {
  using Mode = solvers::DeflationOptions::Mode;
  if (options.deflation.mode == Mode::on) return true;
  return options.type == solvers::SolverType::pk_multilevel && options.deflation.mode == Mode::automatic &&
         options.deflation.automatic_applies(grid);
}

// The adhesive solver (adhesive_contact_solver.cpp) on its variable's grid,
// the zero-padded one on free grids: eight workspace fields (two more for
// the conjugate gradients), the padding flags, the transform's real buffer
// and spectrum, the kernel and stiffness symbols, and the residual history
// (at most 100000 entries; its iteration limit defaults to 20000).
double adhesive_bytes(const Extents& g, const solvers::SolverOptions& settings) {
  const double rows = g.line ? 1.0 : (g.periodic ? g.ny : 2.0 * g.ny);
  const double cols = g.periodic ? g.nx : 2.0 * g.nx;
  const double m = rows * cols;
  const double half = std::floor(cols / 2.0) + 1.0;
  const double fields = settings.adhesion->precondition ? 10.0 : 8.0;
  const double entries = std::min(static_cast<double>(settings.max_iterations.value_or(20000)), 100000.0) + 1.0;
  return (fields * kDouble + 1.0 + kDouble) * m + kComplex * rows * half + 2.0 * kDouble * stored_rows(rows) * half +
         kDouble * entries;
}

// The peak of the solve itself, besides the heights and the initial gap
// the program holds and the fields of the finished steps of a sweep.
double solver_peak(const Grid& grid, const solvers::SolverOptions& settings) {
  const Extents g(grid);
  const double history = kDouble * (static_cast<double>(std::max(settings.iteration_limit(), 0)) + 1.0);
  const bool mixed = settings.precision == solvers::Precision::mixed;
  if (settings.adhesion) return adhesive_bytes(g, settings) + result_bytes(g, history);
  if (is_dense(settings.type)) return dense_bytes(g) + result_bytes(g, history);
  if (settings.type == solvers::SolverType::pk) {
    return level_bytes(g, false, false, mixed) + solve_bytes(g, history, mixed);
  }
  if (settings.type == solvers::SolverType::pk_fourier) {
    return level_bytes(g, true, deflated(grid, settings), mixed) + solve_bytes(g, history, mixed);
  }
  // pk-multilevel: the fine solver is built first and kept. Its fine solve
  // adds its fields; before that the coarse start holds the averaged gap of
  // every coarser level, the first coarser level's solver and solve, and
  // the prolonged start on the fine grid.
  const double fine = level_bytes(g, true, deflated(grid, settings), mixed);
  const Extents coarse = g.coarser();
  const double shrink = g.line ? 0.5 : 0.25;
  const double coarse_gaps = kDouble * g.cells() * shrink / (1.0 - shrink);
  const double coarse_start =
      coarse_gaps + level_bytes(coarse, true, false, mixed) + solve_bytes(coarse, history, mixed) + kDouble * g.cells();
  return fine + std::max(solve_bytes(g, history, mixed), coarse_start);
}

}  // namespace

double solve_memory_estimate(const Grid& grid, const solvers::SolverOptions& settings, std::size_t load_steps,
                             bool gap_in_heights) {
  const Extents g(grid);
  const double cells = g.cells();
  const double steps = static_cast<double>(std::max<std::size_t>(load_steps, 1));
  const double history = kDouble * (static_cast<double>(std::max(settings.iteration_limit(), 0)) + 1.0);
  const double heights_and_gap = 2.0 * kDouble * cells;
  // A sweep keeps each finished step's fields and cluster sizes (at most
  // one cluster per two cells).
  const double kept_step = result_bytes(g, history) + 0.5 * kDouble * cells;
  const double lent = gap_in_heights && steps == 1.0 ? kDouble * cells : 0.0;
  const double solving = heights_and_gap - lent + (steps - 1.0) * kept_step + solver_peak(grid, settings);
  // Writing: the solver is gone; the fields stay, with the contact flags.
  // A sweep's file, and a small result's, is assembled in memory, held twice
  // (HDF5's buffer and the image copied out of it), uncompressed at worst; a
  // larger result is written in place (io::kInMemoryResultBytes). This file
  // size is below the writer's bound, so a file written in place is never
  // counted as one held in memory.
  const double file = kDouble * cells + steps * (3.0 * kDouble * cells + cells + history);
  const bool in_place = steps == 1.0 && file > static_cast<double>(io::kInMemoryResultBytes);
  const double writing = heights_and_gap + steps * kept_step + cells + (in_place ? 0.0 : 2.0 * file);
  return kProgramBytes + std::max(solving, writing);
}

double slab_solve_memory_estimate(const Grid& grid, const solvers::SolverOptions& settings, std::size_t rows,
                                  std::size_t load_steps) {
  const Extents g(grid);
  const double share = g.line ? 1.0 : static_cast<double>(rows) / g.ny;
  const double steps = static_cast<double>(std::max<std::size_t>(load_steps, 1));
  const double history = kDouble * (static_cast<double>(std::max(settings.iteration_limit(), 0)) + 1.0);
  // A sweep keeps its rows of each finished step's fields until the
  // collective writing, and each step's cluster sizes, which every process
  // holds whole (at most one cluster per two cells). The writing after the
  // last step adds that step's contact flags, less than the solver it
  // follows.
  const double kept_steps = (steps - 1.0) * (share * result_bytes(g, history) + 0.5 * kDouble * g.cells());
  // Block deflation on a slab keeps its contact flags and cell lists on its
  // held rows (block_deflation.cpp): its own, counted in the share, and a
  // halo of at most three block rows more (one each side, and the rest of
  // a block row split with a neighbour), with two more flags per held cell
  // (this slab's set and the fetched one).
  double halo_deflation = 0.0;
  if (deflated(grid, settings) && !g.line && rows < static_cast<std::size_t>(g.ny)) {
    const double halo_rows =
        std::min(3.0 * static_cast<double>(settings.deflation.block), g.ny - static_cast<double>(rows));
    const double held_cells = (static_cast<double>(rows) + halo_rows) * g.nx;
    halo_deflation = (1.0 + 3.0 * kDouble) * halo_rows * g.nx + 2.0 * held_cells;
  }
  // The adhesive energy's circulant form on a free 2D grid transforms the
  // padding rows through a second pruned padded transform of its own
  // (slab_spectral_transforms.cpp: its buffer, 2ny complex values per held
  // column) and keeps a copy of the kernel's folded multiplier beside its
  // stiffness; the serial form has one whole transform.
  const double adhesive_form = settings.adhesion && !g.periodic && !g.line
                                   ? kComplex * 2.0 * g.ny * (g.nx + 1.0) + kDouble * (g.ny + 1.0) * (g.nx + 1.0)
                                   : 0.0;
  return kProgramBytes + share * (2.0 * kDouble * g.cells() + solver_peak(grid, settings) + adhesive_form) +
         halo_deflation + kept_steps;
}

double solve_stress_memory_estimate(const Grid& grid, std::size_t depth_count, bool coated, bool shear,
                                    bool body1_tractions) {
  if (depth_count == 0) return 0.0;
  const double cells = static_cast<double>(grid.size());
  const double body1_shear = body1_tractions && shear ? 2.0 * kDouble * cells : 0.0;
  return kProgramBytes + 6.0 * kDouble * cells + body1_shear + stress::stress_memory_estimate(grid, coated, shear);
}

double stress_command_memory_estimate(const Grid& grid, bool coated, bool shear, double share) {
  // Pressure, or pressure and two shear tractions, twice, and body 1's two
  // negated shear tractions: 2 or 8 arrays of doubles.
  const double tractions = (shear ? 8.0 : 2.0) * kDouble * static_cast<double>(grid.size());
  return kProgramBytes + share * (tractions + stress::stress_memory_estimate(grid, coated, shear));
}

double generate_memory_estimate(const Grid& grid) {
  const Extents g(grid);
  const double rows = g.line ? 1.0 : g.ny;
  // The synthesis transform (and the spectral slope of the statistics
  // after it): spectrum, input and output; and the heights copied out.
  const double transform = kComplex * rows * (std::floor(g.nx / 2.0) + 1.0) + 2.0 * kDouble * g.cells();
  return kProgramBytes + transform + kDouble * g.cells();
}

namespace {

// The first whole number in `path`, or nothing ("max" in cgroup v2 files).
std::optional<double> number_in(const fs::path& path) {
  std::ifstream in(path);
  std::string word;
  if (!(in >> word)) return std::nullopt;
  if (word.empty() || !std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return std::stod(word);
}

// The value of `key` in a "key value" file (memory.stat).
std::optional<double> stat_value(const fs::path& path, std::string_view key) {
  std::ifstream in(path);
  std::string name;
  double value = 0.0;
  while (in >> name >> value) {
    if (name == key) return value;
  }
  return std::nullopt;
}

std::optional<AvailableMemory> mem_available(const fs::path& proc) {
  std::ifstream in(proc / "meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name;
    double kib = 0.0;
    std::string unit;
    if (fields >> name >> kib >> unit && name == "MemAvailable:" && unit == "kB") {
      return AvailableMemory{kib * 1024.0, "MemAvailable in /proc/meminfo"};
    }
  }
  return std::nullopt;
}

// This process's cgroup paths from /proc/self/cgroup: cgroup v2's ("0::/a/b")
// and the v1 memory controller's ("4:memory:/a/b").
struct CgroupPaths {
  std::optional<std::string> unified;
  std::optional<std::string> memory;
};

CgroupPaths cgroup_paths(const fs::path& proc) {
  CgroupPaths paths;
  std::ifstream in(proc / "self" / "cgroup");
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find(':');
    const std::size_t second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    if (line.compare(0, first, "0") == 0 && controllers.empty()) paths.unified = path;
    std::istringstream list(controllers);
    for (std::string controller; std::getline(list, controller, ',');) {
      if (controller == "memory") paths.memory = path;
    }
  }
  return paths;
}

// A limit this large means none (v1 writes 2^63 rounded down to a page).
constexpr double kNoLimit = 0x1p62;

// What a cgroup directory still allows: its limit less its usage, the page
// cache it can drop (inactive_file) counted as free.
std::optional<double> cgroup_room(const fs::path& directory, const char* limit_file, const char* usage_file) {
  const std::optional<double> limit = number_in(directory / limit_file);
  if (!limit || *limit >= kNoLimit) return std::nullopt;
  const double usage = number_in(directory / usage_file).value_or(0.0);
  const double reclaimable = stat_value(directory / "memory.stat", "inactive_file").value_or(0.0);
  return std::max(0.0, *limit - usage + std::min(reclaimable, usage));
}

// The tightest limit on the way from the process's cgroup up to the root,
// and the file that sets it.
std::optional<AvailableMemory> tightest_room(const fs::path& root, const std::string& own, const char* limit_file,
                                             const char* usage_file) {
  std::optional<AvailableMemory> room;
  fs::path relative = fs::path(own).relative_path();
  for (;;) {
    const fs::path directory = root / relative;
    if (fs::is_directory(directory)) {
      const std::optional<double> here = cgroup_room(directory, limit_file, usage_file);
      if (here && (!room || *here < room->bytes)) {
        room = AvailableMemory{*here,
                               fmt::format("the cgroup limit in {} less its usage", (directory / limit_file).string())};
      }
    }
    if (relative.empty()) break;
    relative = relative.parent_path();
  }
  return room;
}

}  // namespace

std::optional<AvailableMemory> available_memory(const fs::path& proc, const fs::path& cgroup) {
  std::optional<AvailableMemory> available = mem_available(proc);
  const CgroupPaths paths = cgroup_paths(proc);
  for (std::optional<AvailableMemory> room :
       {tightest_room(cgroup, paths.unified.value_or("/"), "memory.max", "memory.current"),
        tightest_room(cgroup / "memory", paths.memory.value_or("/"), "memory.limit_in_bytes",
                      "memory.usage_in_bytes")}) {
    if (room && (!available || room->bytes < available->bytes)) available = std::move(room);
  }
  return available;
}

std::string format_bytes(double bytes) {
  constexpr std::array<const char*, 7> kUnits{"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  std::size_t unit = 0;
  while (bytes >= 1024.0 && unit + 1 < kUnits.size()) {
    bytes /= 1024.0;
    ++unit;
  }
  if (unit == 0) return fmt::format("{:.0f} B", bytes);
  return fmt::format("{:.3g} {}", bytes, kUnits[unit]);
}

}  // namespace halfspace
