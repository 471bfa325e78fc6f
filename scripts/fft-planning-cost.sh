#!/bin/sh
# FFTW planning cost with and without wisdom, against the transform time it
# buys: for each grid size and boundary, the transforms of a pk-fourier solve
# planned with estimate, with measure from scratch (empty wisdom file) and with
# measure again (the wisdom saved by the run before). One process per line.
#
#   scripts/fft-planning-cost.sh [BUILD_DIR] [THREADS] [SIZES...]
#
# Columns: n boundary planning threads wisdom plan_s pair_s... (pair_s: one
# forward + backward pair of each transform; free grids list the padded 2n
# transform first). The wisdom file is a temporary one, never the user's.
set -eu
build=${1:-build}
threads=${2:-1}
if [ $# -ge 2 ]; then shift 2; else shift $#; fi
sizes=${*:-256 512 1024 2048 4096}
tool="$build/bench/fft_planning_cost"
[ -x "$tool" ] || { echo "error: $tool not found: build with -DHALFSPACE_BUILD_BENCH=ON" >&2; exit 1; }

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "# $(date -u +%Y-%m-%dT%H:%MZ) $(uname -m) threads=$threads load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# n boundary planning threads wisdom plan_s pair_s..."
for n in $sizes; do
  # Fewer pairs on large grids: the timing is long enough to be stable.
  pairs=$(( n >= 2048 ? 5 : 20 ))
  for boundary in periodic free; do
    wisdom="$dir/wisdom-$n-$boundary"
    HALFSPACE_FFTW_WISDOM=off "$tool" "$n" "$boundary" estimate "$threads" "$pairs"
    HALFSPACE_FFTW_WISDOM="$wisdom" "$tool" "$n" "$boundary" measure "$threads" "$pairs"
    HALFSPACE_FFTW_WISDOM="$wisdom" "$tool" "$n" "$boundary" measure "$threads" "$pairs"
  done
done
