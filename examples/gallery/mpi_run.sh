#!/usr/bin/env bash
# Gallery: a rough contact on several processes (docs/gallery.md#mpi-run).
#   examples/gallery/mpi_run.sh [OUT_DIR]
# HALFSPACE_MPI: the MPI build's program [build-mpi/bin/halfspace];
# MPIEXEC [mpirun]; PROCESSES [2]; QUICK=1: a 64x64 grid (CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE_MPI:-$here/../../build-mpi/bin/halfspace}"
grid=512x512
[ "${QUICK:-0}" = 1 ] && grid=64x64
# MPIEXEC_FLAGS: more flags for it (e.g. --oversubscribe).
run=("${MPIEXEC:-mpirun}" ${MPIEXEC_FLAGS:-} -np "${PROCESSES:-2}" "$halfspace")
# Each process makes and keeps its rows of the surface, solves on them and
# writes them into the one result file (parallel HDF5); the first process
# adds the XDMF sidecar.
"${run[@]}" generate --kind self-affine --grid "$grid" --size 1e-3x1e-3 --rms-slope 0.1 --seed 2 \
  --output "$out/mpi_rough.h5" --quiet
"${run[@]}" solve --height-map "$out/mpi_rough.h5" --boundary periodic --E-star 1e9 --mean-pressure 2e6 \
  --output "$out/mpi_result.h5" --quiet
"${PYTHON:-python3}" "$here/../../scripts/halfspace_plot.py" maps "$out/mpi_result.h5" --out "$out/mpi_result_maps.png"
