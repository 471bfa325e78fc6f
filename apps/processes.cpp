// The serial program runs as one process; with HALFSPACE_MPI the functions
// of processes.hpp that differ are apps/mpi/'s.
#include "processes.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "activity.hpp"

namespace halfspace::app {

io::ResultPressure read_stress_input(const std::filesystem::path& path) {
  const Activity activity(fmt::format("reading {}", path.string()));
  return io::read_result_pressure(path);
}

StressPlace whole_stress_place(io::ResultPressure input) {
  StressPlace place{.layout = solvers::serial_layout(), .input = std::move(input)};
  place.write_file = [](const std::filesystem::path& path, stress::SubsurfaceStress& stresses,
                        const stress::SurfaceTractions& tractions, std::span<const double> depths,
                        const io::StressFileMetadata& metadata) {
    return io::write_stress_file(path, stresses, tractions, depths, metadata);
  };
  return place;
}

#ifndef HALFSPACE_MPI

struct Processes::Session {};
Processes::Processes(int& /*argc*/, char**& /*argv*/) {}
Processes::~Processes() = default;
int process_count() {
  return 1;
}
bool prints_messages() {
  return true;
}
SolveSetup make_setup_everywhere(const std::function<SolveSetup(const SurfaceSharing& share)>& make) {
  return make(SurfaceSharing{});
}
std::optional<int> run_distributed_solve(const SolveSetup& /*setup*/) {
  return std::nullopt;
}
void agree_everywhere(const std::function<void()>& step) {
  step();
}
int run_on_first_process(const std::function<int()>& run) {
  return run();
}
surface::SurfaceStatistics generate_distributed(const Grid& /*grid*/, const SurfaceSource& /*source*/,
                                                io::HeightMapMetadata& /*metadata*/,
                                                const std::filesystem::path& /*output*/) {
  throw std::logic_error("generate_distributed: the serial build runs one process");
}
int run_stress_everywhere(const std::filesystem::path& path, const std::function<int(StressPlace& place)>& run) {
  StressPlace place = whole_stress_place(read_stress_input(path));
  return run(place);
}
int run_film_everywhere(const std::function<HeightMap()>& read,
                        const std::function<int(HeightMap& map, const FilmPlace& place)>& run, FilmSpread /*spread*/) {
  HeightMap map = read();
  return run(map, FilmPlace{});
}

#endif

}  // namespace halfspace::app
