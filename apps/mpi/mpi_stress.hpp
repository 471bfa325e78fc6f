// `mpirun -np N halfspace stress RESULT ...`: the first process reads the
// result, every process computes the stresses of its rows of a 2D result
// (mpi::DistributedLayout) and all write their rows of the stress file at
// once (the parallel HDF5), as the solve command's --stress-depths does.
// HALFSPACE_MPI builds only.
#pragma once

#include <filesystem>
#include <functional>

#include "../processes.hpp"

namespace halfspace::app {

// processes.hpp's run_stress_everywhere.
int run_stress_on_slabs(const std::filesystem::path& path, const std::function<int(StressPlace& place)>& run);

}  // namespace halfspace::app
