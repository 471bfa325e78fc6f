#!/usr/bin/env bash
# Install what is missing, build, run the whole test suite, and check the
# C++ formatting.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
ctest --test-dir "${HALFSPACE_BUILD_DIR:-$root/build}" --output-on-failure -j "$(nproc)"
# The MPI build and its distributed tests against the serial program.
"$root/scripts/test-mpi.sh"
# Each reader's fuzzer briefly, from a fixed seed so that CI repeats the run
# checked here; scripts/fuzz.sh alone explores from random seeds.
HALFSPACE_FUZZ_SEED="${HALFSPACE_FUZZ_SEED:-1}" "$root/scripts/fuzz.sh" 20
# The Python package: `pip install .` into a virtual environment, and its tests.
"$root/scripts/test-python.sh"
# The sources must match .clang-format (scripts/check-format.sh --fix repairs them).
"$root/scripts/check-format.sh"
