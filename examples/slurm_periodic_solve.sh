#!/usr/bin/env bash
# A distributed periodic solve on a Slurm cluster: 16 MPI processes on 4
# nodes, 8 OpenMP threads each (docs/usage.md#running-on-a-cluster).
# Submit with `sbatch examples/slurm_periodic_solve.sh MAP.h5 OUT.h5`; the
# halfspace program must be an MPI build (cmake -DHALFSPACE_MPI=ON).
#SBATCH --job-name=halfspace
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=4
#SBATCH --cpus-per-task=8
#SBATCH --mem=0
#SBATCH --time=02:00:00
set -euo pipefail

map="${1:?usage: sbatch slurm_periodic_solve.sh MAP.h5 OUT.h5}"
output="${2:?usage: sbatch slurm_periodic_solve.sh MAP.h5 OUT.h5}"
program="${HALFSPACE_PROGRAM:-halfspace}"

# One OpenMP team per process, on the cores Slurm gave it; threads wait
# passively so that they leave the cores to MPI's progress.
export OMP_NUM_THREADS="${SLURM_CPUS_PER_TASK}"
export OMP_PLACES=cores OMP_PROC_BIND=close OMP_WAIT_POLICY=passive

# srun starts the processes with Slurm's binding: each gets its
# --cpus-per-task cores, and --threads uses them all. The solver must be one
# that is distributed (pk-multilevel, the default, pk-fourier or pk, on
# periodic 2D grids). FFTW-MPI
# measures its plans in every run (no wisdom file yet): a few seconds to a
# minute on large grids; --fft-planning estimate skips it.
srun --cpu-bind=cores "$program" solve \
  --height-map "$map" --boundary periodic \
  --E-star 1e11 --mean-pressure 1e7 \
  --threads "${SLURM_CPUS_PER_TASK}" \
  --output "$output"
