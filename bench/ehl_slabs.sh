#!/usr/bin/env bash
# The EHL point contact on several processes against one: Hamrock & Dowson's
# W = 3e-7, U = 1e-11, G = 5000 (ehl/ehl_case.hpp: a ball of R = 10 mm,
# E* = 110 GPa, 6.6 N, Roelands oil of 0.04 Pa s and alpha = 2.27e-8 1/Pa,
# rolling at 0.55 m/s) on a GRID^2 map of 5 Hertz radii per side; or, with
# CASE mixed, the mixed film of bench/mixed_measured.sh's measured window
# (metropro-1, resampled to GRID^2, the 10 mm ball, 5.04 N) at SPEED m/s
# [1e-3: contact carries 0.5 % of the load at 128^2]; solved by
#   serial-2t   the MPI program, 1 process of 2 OpenMP threads
#   mpi-2x1     the MPI program, 2 processes of 1 thread
# alternating, REPEATS rounds; prints a Markdown table of medians: the
# solve's own time (the file's solve_seconds, the slowest process's), the
# run's wall time, the Newton steps, and the peak resident memory of each
# process (GNU time); then how far the two films are apart.
# Usage: bench/ehl_slabs.sh MPI_PROGRAM [GRID] [REPEATS] [CASE] [SPEED]
set -euo pipefail
program="$(realpath "$1")"
side="${2:-1024}"
repeats="${3:-2}"
case_name="${4:-ehl}"
speed="${5:-1e-3}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=passive HALFSPACE_FFTW_WISDOM=off

case "$case_name" in
  ehl)
    "$program" generate --kind sphere --grid "${side}x${side}" --size 3.83e-4x3.83e-4 --radius 1e-2 --output ball.h5 \
      --quiet
    film_args=(lubricate --height-map ball.h5 --viscosity 0.04 --entrainment-velocity 0.55 --force 6.6 --E-star 1.1e11
      --piezoviscosity roelands --pressure-viscosity 2.27e-8 --quiet)
    ;;
  mixed)
    map="$root/../shared/data/topography/metropro-1.h5"
    [[ -f "$map" ]] || { echo "ehl_slabs.sh: $map not found" >&2; exit 1; }
    "$program" generate --kind sphere --grid "${side}x${side}" --size 2.81152519165e-4 --radius 1e-2 --output ball.h5 \
      --quiet
    film_args=(lubricate --height-map "$map" --window 200,150,256,256 --detrend plane --resample "${side}x${side}"
      --roughness ball.h5 --mixed --viscosity 0.04 --entrainment-velocity "$speed"
      --sliding-velocity "$(awk -v u="$speed" 'BEGIN { print u / 2 }')" --force 5.04 --E-star 1.1e11
      --pressure-viscosity 2.27e-8 --piezoviscosity roelands --limiting-shear-slope 0.05 --quiet)
    ;;
  *) echo "ehl_slabs.sh: CASE is ehl or mixed, not $case_name" >&2; exit 1 ;;
esac

# One run of configuration $1: "solve_seconds wall_seconds newton_steps rss_kib_per_process".
run() {
  local start end rss
  start="$(date +%s.%N)"
  case "$1" in
    serial-2t) OMP_NUM_THREADS=2 /usr/bin/time -f "%M" -o rss "$program" "${film_args[@]}" --output out.h5 ;;
    mpi-2x1) mpirun --oversubscribe --bind-to none -np 2 -x OMP_NUM_THREADS=1 sh -c \
      '/usr/bin/time -f "%M" -o "rss.$OMPI_COMM_WORLD_RANK" "$0" "$@"' "$program" "${film_args[@]}" \
      --output out.h5; cat rss.0 rss.1 | paste -sd/ > rss ;;
  esac
  end="$(date +%s.%N)"
  rss="$(cat rss)"
  /usr/bin/python3 -c "
import h5py
f = h5py.File('out.h5', 'r')
print(f.attrs['solve_seconds'], $end - $start, f.attrs['iterations'], '$rss')"
  mv out.h5 "$1.h5"
}

configs=(serial-2t mpi-2x1)
for ((k = 0; k < repeats; ++k)); do
  for c in "${configs[@]}"; do echo "$c $(run "$c")" >> runs.txt; done
done
echo "$case_name film on ${side}^2, $repeats rounds alternating, $(nproc) cores, load average at the end:" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| run | solve s (median) | wall s (median) | Newton steps | peak RSS per process (MiB) |"
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
/usr/bin/python3 -c "
import h5py, numpy as np
a, b = h5py.File('mpi-2x1.h5', 'r'), h5py.File('serial-2t.h5', 'r')
worst = max(np.max(np.abs(a[n][()] - b[n][()])) / np.max(np.abs(b[n][()])) for n in ('pressure', 'film'))
share = ''
if 'contact_load_fraction' in b.attrs:
    share = (f'; contact load share {a.attrs[\"contact_load_fraction\"]:.6g} against '
             f'{b.attrs[\"contact_load_fraction\"]:.6g}')
print(f'\nmpi-2x1 against serial-2t: pressure and film within {worst:.1e} of their largest values; central film '
      f'{a.attrs[\"central_film_thickness\"]:.6e} against {b.attrs[\"central_film_thickness\"]:.6e} m{share}')"
