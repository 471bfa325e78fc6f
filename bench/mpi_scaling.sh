#!/usr/bin/env bash
# Strong scaling of the distributed solve on this machine: one rough surface
# (periodic, or free with BOUNDARY = free) solved by SOLVER (pk-fourier
# unless given) as
#   serial-1t   the serial program, 1 thread
#   serial-2t   the serial program, 2 OpenMP threads
#   mpi-1x1     the MPI program, 1 process (FFTW-MPI on one process)
#   mpi-2x1     the MPI program, 2 processes of 1 thread
# alternating, REPEATS rounds; prints a Markdown table of medians: the solve's
# own time (the result's solve_seconds), the whole run's wall time, the
# iterations, and the peak resident memory of each process (GNU time).
# Usage: bench/mpi_scaling.sh SERIAL_PROGRAM MPI_PROGRAM [GRID] [REPEATS] [BOUNDARY] [SOLVER]
set -euo pipefail
serial="$(realpath "$1")"
mpi="$(realpath "$2")"
grid="${3:-2048x2048}"
repeats="${4:-3}"
boundary="${5:-periodic}"
solver="${6:-pk-fourier}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=passive HALFSPACE_FFTW_WISDOM=off

"$serial" generate --kind self-affine --grid "$grid" --size 1e-3x1e-3 --hurst 0.8 --rms-slope 0.1 --seed 1 \
  --output surface.h5 --quiet
solve_args=(solve --height-map surface.h5 --boundary "$boundary" --E-star 1e11 --mean-pressure 5e7
  --solver "$solver" --fft-planning estimate --quiet)

# One run of configuration $1: "solve_seconds wall_seconds iterations rss_kib_per_process".
run() {
  local start end rss
  start="$(date +%s.%N)"
  case "$1" in
    serial-1t) /usr/bin/time -f "%M" -o rss "$serial" "${solve_args[@]}" --threads 1 --output out.h5 ;;
    serial-2t) /usr/bin/time -f "%M" -o rss "$serial" "${solve_args[@]}" --threads 2 --output out.h5 ;;
    mpi-1x1) mpirun --oversubscribe --bind-to none -np 1 /usr/bin/time -f "%M" -o rss "$mpi" "${solve_args[@]}" \
      --threads 1 --output out.h5 ;;
    mpi-2x1) mpirun --oversubscribe --bind-to none -np 2 sh -c \
      '/usr/bin/time -f "%M" -o "rss.$OMPI_COMM_WORLD_RANK" "$0" "$@"' "$mpi" "${solve_args[@]}" --threads 1 \
      --output out.h5; cat rss.0 rss.1 | paste -sd/ > rss ;;
  esac
  end="$(date +%s.%N)"
  rss="$(cat rss)"
  /usr/bin/python3 -c "
import h5py, sys
f = h5py.File('out.h5', 'r')
print(f.attrs['solve_seconds'], $end - $start, f.attrs['iterations'], '$rss')"
  mv out.h5 "$1.h5"
}

configs=(serial-1t serial-2t mpi-1x1 mpi-2x1)
for ((k = 0; k < repeats; ++k)); do
  for c in "${configs[@]}"; do echo "$c $(run "$c")" >> runs.txt; done
done
echo "grid $grid ($boundary), solver $solver, $repeats rounds alternating, $(nproc) cores, load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| run | solve s (median) | wall s (median) | iterations | peak RSS per process (MiB) |"
echo "|---|---|---|---|---|"
for c in "${configs[@]}"; do
  grep "^$c " runs.txt | /usr/bin/python3 -c "
import statistics, sys
rows = [line.split() for line in sys.stdin]
solve = statistics.median(float(r[1]) for r in rows)
wall = statistics.median(float(r[2]) for r in rows)
rss = '/'.join(str(round(int(v) / 1024)) for v in rows[-1][4].split('/'))
print(f'| $c | {solve:.2f} | {wall:.2f} | {rows[-1][3]} | {rss} |')"
done
# The 2-process result against the serial one (the last round's).
/usr/bin/python3 -c "
import h5py, numpy as np
a, b = h5py.File('mpi-2x1.h5', 'r'), h5py.File('serial-1t.h5', 'r')
p, q = a['pressure'][()], b['pressure'][()]
print(f'\nmpi-2x1 against serial-1t: pressure within {np.max(np.abs(p - q)) / np.max(np.abs(q)):.1e} of its '
      f'largest value, {np.count_nonzero((p > 0) != (q > 0))} cells differ in contact; deflation block '
      f'{a.attrs[\"deflation_block\"]} against {b.attrs[\"deflation_block\"]}')"
