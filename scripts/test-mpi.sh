#!/usr/bin/env bash
# The MPI build (-DHALFSPACE_MPI=ON) in its own directory: only the program
# and the distributed tests, which run `mpiexec -np 1, 2, 3 halfspace solve`
# against the serial build's program (scripts/build.sh first), the slab
# statistics, the slab self-affine surface and the frictional solve on slabs
# against the serial ones, and the communicator's sums; the target
# halfspace_mpi_tests (tests/CMakeLists.txt) builds all of them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
serial_build="${HALFSPACE_BUILD_DIR:-$root/build}"
build="${HALFSPACE_MPI_BUILD_DIR:-$root/build-mpi}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFSPACE_MPI=ON -DHALFSPACE_BUILD_BENCH=OFF \
  -DHALFSPACE_SERIAL_PROGRAM="$serial_build/bin/halfspace" "$@"
cmake --build "$build" -j "$(nproc)" --target halfspace_mpi_tests
ctest --test-dir "$build" --output-on-failure
