#!/usr/bin/env bash
# The mixed film on a measured map: metropro-1's 256^2 window at (200, 150)
# (../shared/data/topography), plane-detrended, resampled to GRID^2, against
# a ball of R = 10 mm over the same 281 um, 5.04 N, Roelands oil (0.04 Pa s,
# 2.27e-8 1/Pa), E* = 110 GPa, the sliding speed half the entrainment speed.
# It is the case of docs/performance.md's issue-30 rows: at 3e-4 m/s the
# film is in the transition (contact carries 0.25 of the load at 128^2,
# 0.16 at 256^2), and each grid's coarse levels are the window resampled.
# Usage: bench/mixed_measured.sh [PROGRAM] [GRID] [SPEED] [THREADS] [TRACE]
#   PROGRAM  the halfspace executable [build/bin/halfspace]
#   GRID     cells per side of the resampled window [128]
#   SPEED    entrainment speed, m/s [3e-4]
#   THREADS  OpenMP threads [1]
#   TRACE    where to write the run's trace (lubricate --trace: one line
#            per Newton solve as it ends) [none]
# Prints the CPU and wall seconds, the peak resident size, and the
# program's summary (Newton steps, film, contact share), or its error.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build/bin/halfspace}")"
side="${2:-128}"
speed="${3:-3e-4}"
threads="${4:-1}"
trace=()
if [[ -n "${5:-}" ]]; then trace=(--trace "$(realpath -m "$5")"); fi
map="$root/../shared/data/topography/metropro-1.h5"
if [[ ! -f "$map" ]]; then
  echo "mixed_measured.sh: $map not found (the shared topography data sits beside the project)" >&2
  exit 1
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "mixed_measured.sh: /usr/bin/time not found (Debian package time)" >&2
  exit 1
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export HALFSPACE_FFTW_WISDOM="$work/wisdom"

# The window's 256 pixels of 1.0982520 um; the ball must have the resampled
# map's spacing to about 1e-5.
"$program" generate --kind sphere --grid "${side}x${side}" --size 2.81152519165e-4 --radius 1e-2 \
  --output ball.h5 --quiet
sliding="$(awk -v u="$speed" 'BEGIN { print u / 2 }')"
status=0
OMP_NUM_THREADS="$threads" /usr/bin/time -f "%U CPU s, %e wall s, %M KB peak" -o time.txt \
  "$program" lubricate --height-map "$map" --window 200,150,256,256 --detrend plane \
  --resample "${side}x${side}" --roughness ball.h5 --mixed --viscosity 0.04 \
  --entrainment-velocity "$speed" --sliding-velocity "$sliding" --force 5.04 --E-star 1.1e11 \
  --pressure-viscosity 2.27e-8 --piezoviscosity roelands --limiting-shear-slope 0.05 \
  "${trace[@]}" --output film.h5 > out.txt 2>&1 || status=$?
echo "metropro-1 window resampled to ${side}^2, ${speed} m/s, ${threads} thread(s): $(cat time.txt)"
grep -E "load  |film  |contact  |error" out.txt || true
exit "$status"
