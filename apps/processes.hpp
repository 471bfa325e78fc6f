// The processes the program runs as: one, or (built with HALFSPACE_MPI) the
// MPI processes mpirun starts, which all run the same command. Only here and
// in apps/mpi/ (which defines these functions in an MPI build,
// processes.cpp in a serial one) does the program know the difference.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <variant>

#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/height_map.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/result_pressure_reader.hpp"
#include "halfspace/io/stress_writer.hpp"
#include "halfspace/linalg/communicator.hpp"
#include "halfspace/lubrication/film_rows.hpp"
#include "halfspace/lubrication/flow_conditions.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/solvers/layout.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "solve_setup.hpp"

namespace halfspace::app {

// For the program's lifetime: MPI's setup and teardown in an MPI build,
// nothing otherwise.
class Processes {
 public:
  Processes(int& argc, char**& argv);
  ~Processes();
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

 private:
  struct Session;  // MPI's (mpi::Session) in an MPI build, empty otherwise
  std::unique_ptr<Session> session_;
};

// How many processes run the program (1 in the serial build).
int process_count();

// Whether this process prints (messages, progress, summaries): the only one,
// or the first of the MPI processes.
bool prints_messages();

// The setup of a solve on every process: make(share) checks the options and
// makes the surface through `share` (make_solve_setup). In an MPI run every
// process checks the options and makes or reads its rows of the surface (or
// the first reads it whole and hands the others their rows: see
// SurfaceSharing); if anything fails on any process, it throws on all, the
// error of the first process that failed (one message, one exit code, no
// process left waiting). The serial build calls make(SurfaceSharing{}).
SolveSetup make_setup_everywhere(const std::function<SolveSetup(const SurfaceSharing& share)>& make);

// Runs the single solve of `setup` distributed over the MPI processes and
// returns the exit code; nullopt if it is to be solved by this process
// alone (always in the serial build; on one MPI process, when the
// distributed solver does not take it). Throws InputError, on every process,
// for a solve that several processes cannot do yet.
std::optional<int> run_distributed_solve(const SolveSetup& setup);

// Runs `step` on every process; if it failed on any, throws on all the
// error of the first process that failed (the serial build: step()).
void agree_everywhere(const std::function<void()>& step);

// Runs `run` on the first process alone and returns its exit code on every
// process, the others waiting: for what one process does whole (a 1D grid,
// one row, which slabs of rows cannot split; the paper's small line
// contacts). A failure throws on all, as agree_everywhere (the serial build:
// run()).
int run_on_first_process(const std::function<int()>& run);

// What `halfspace generate` makes: a self-affine surface or a built-in shape.
using SurfaceSource = std::variant<surface::SelfAffineSpec, geometry::SurfaceSpec>;

// On several MPI processes: the surface of `source` on the 2D `grid`, each
// process its rows, written into `output` by all at once with `metadata`
// and the statistics (rms_height, rms_slope, appended to its numbers as the
// serial generate appends them), which it returns. Throws std::logic_error
// in the serial build (process_count() is 1 there).
surface::SurfaceStatistics generate_distributed(const Grid& grid, const SurfaceSource& source,
                                                io::HeightMapMetadata& metadata, const std::filesystem::path& output);

// Where the stress command runs: the whole result on this process, or on
// several MPI processes each process's rows of a 2D result's fields, the
// hooks then collective.
struct StressPlace {
  const solvers::Layout& layout;  // what SubsurfaceStress is made on
  io::ResultPressure input;       // grid and coating whole; the fields the rows `layout` holds here
  bool first = true;              // the first (or only) process: it prints
  // Writes the stress file (io::write_stress_file's) of the rows held here.
  std::function<stress::VonMisesMaximum(const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                                        const stress::SurfaceTractions& tractions, std::span<const double> depths,
                                        const io::StressFileMetadata& metadata)>
      write_file{};
  // Runs a step everywhere, every process learning of a failure on any.
  std::function<void(const std::function<void()>& step)> agree = [](const std::function<void()>& step) { step(); };
};

// The stress command's input, read whole (io::read_result_pressure).
io::ResultPressure read_stress_input(const std::filesystem::path& path);
// The whole of `input` on this process: serial_layout(), io::write_stress_file.
StressPlace whole_stress_place(io::ResultPressure input);

// Reads the result file `path` and returns run(place) at the place of its
// stresses. One process (and the serial build): the whole result here. Several
// MPI processes: the first reads the file and hands every process the grid,
// the coating and its rows of the fields (a 1D result, one row, is run by the
// first process alone as one process runs it, the others waiting); a
// failure on any process throws on all (the first failure's error).
int run_stress_everywhere(const std::filesystem::path& path, const std::function<int(StressPlace& place)>& run);

// Where the lubricate command's film runs: the whole height map here, or on
// several MPI processes each process's rows of a 2D map, the hooks then
// collective.
struct FilmPlace {
  bool whole = true;          // the whole map here
  bool first = true;          // the first (or only) process: it prints
  std::size_t first_row = 0;  // the map's rows held here begin at this row of the whole map
  // The processes sharing a Stribeck sweep's speeds, each with the whole map
  // (lubrication::stribeck_sweep); null: the whole sweep here.
  const linalg::Communicator* sweep_processes = nullptr;
  // The film's rows for the solvers (lubrication/film_rows.hpp) on the
  // whole film's grid under its conditions: null for the whole film.
  std::function<std::unique_ptr<lubrication::FilmRows>(const Grid& grid, const lubrication::FlowConditions& conditions)>
      film_rows =
          [](const Grid&, const lubrication::FlowConditions&) { return std::unique_ptr<lubrication::FilmRows>(); };
  // The influence operator's transforms on the film's grid, planned so:
  // the slabs of rows held here; null: the serial ones of the whole grid.
  std::function<std::shared_ptr<operators::SpectralTransforms>(const Grid& grid, FftPlanning planning)> transforms =
      [](const Grid&, FftPlanning) { return std::shared_ptr<operators::SpectralTransforms>(); };
  // Writes the result file: fill(root) writes each field's rows held here
  // (Hdf5Node::write_dataset_rows from first_row); `bound` bounds the
  // file's bytes (the space reserved before a parallel write).
  std::function<void(const std::filesystem::path& path, std::uint64_t bound,
                     const std::function<void(const io::Hdf5Node& root)>& fill)>
      write_file = [](const std::filesystem::path& path, std::uint64_t /*bound*/,
                      const std::function<void(const io::Hdf5Node& root)>& fill) { io::write_hdf5_file(path, fill); };
};

// How a film's work is spread over several processes: run by the first
// alone; on slabs of rows (the films whose solvers run on rows: the rigid
// film's, lubrication/film_rows.hpp, and the EHL film's on a distributed
// operator); or a Stribeck sweep's speeds shared out.
enum class FilmSpread { first_process, row_slabs, sweep_speeds };

// Reads the height map with read() and returns run(map, place). One process
// (and the serial build): the whole map here. Several MPI processes: the
// first reads the map whole (a failure throws on every process); with
// row_slabs it hands every process its rows of a 2D map (map.heights; the
// other members are the whole map's), and all run; with sweep_speeds every
// process gets the whole map and runs with place.sweep_processes set; a
// profile or one row on slabs, and first_process, are run by the first
// process alone as one process runs them, the others waiting. A failure
// that only some processes meet while running ends them all.
int run_film_everywhere(const std::function<HeightMap()>& read,
                        const std::function<int(HeightMap& map, const FilmPlace& place)>& run, FilmSpread spread);

}  // namespace halfspace::app
