#!/usr/bin/env bash
# Two solves started together, each with the default thread count, against
# one solve alone (issue 16: on a shared machine each must finish within
# 2.5x of the solve alone). Runs both OpenMP waiting modes:
#   spinning  GOMP_SPINCOUNT=300000, GNU OpenMP's own default (the program's
#             behaviour before it chose passive waiting itself)
#   passive   the program's default now (OMP_WAIT_POLICY=passive)
#   spinN     GOMP_SPINCOUNT=N, a short spin before sleeping (e.g. spin10000)
# Usage: [MODES="spinning spin10000 passive"] bench/concurrent_solves.sh [PROGRAM] [GRID] [REPEATS]
#   PROGRAM  the halfspace executable [build/bin/halfspace]
#   GRID     cells of the rough periodic surface solved [1024x1024]
#   REPEATS  rounds per mode; medians are reported [3]
# Prints a Markdown table (bench/results/<date>-concurrent.md keeps one).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build/bin/halfspace}")"
grid="${2:-1024x1024}"
repeats="${3:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
# Wisdom of its own, so that planning happens once, in the warm-up.
export HALFSPACE_FFTW_WISDOM="$work/wisdom"

"$program" generate --kind self-affine --grid "$grid" --size 1e-3 --hurst 0.8 --rms-slope 0.1 --seed 1 \
  --output surface.h5 --quiet

# Seconds one solve takes; $1 names its output, the environment comes from
# the caller.
solve() {
  local start end
  start="$(date +%s.%N)"
  "$program" solve --height-map surface.h5 --boundary periodic --E-star 1e11 --mean-pressure 2e7 \
    --output "$1" --quiet
  end="$(date +%s.%N)"
  echo "$end - $start" | bc -l
}

median() {
  sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# Runs `repeats` rounds of: one solve alone, then two together. Prints the
# medians: alone, first of the pair, second of the pair.
measure() {
  local alone=() first=() second=()
  for ((k = 0; k < repeats; ++k)); do
    alone+=("$(solve alone.h5)")
    solve a.h5 > a.txt &
    local pid_a=$!
    solve b.h5 > b.txt &
    local pid_b=$!
    wait "$pid_a" "$pid_b"
    first+=("$(cat a.txt)")
    second+=("$(cat b.txt)")
  done
  printf '%s\n' "${alone[@]}" | median
  printf '%s\n' "${first[@]}" | median
  printf '%s\n' "${second[@]}" | median
}

unset OMP_WAIT_POLICY GOMP_SPINCOUNT OMP_NUM_THREADS
solve warmup.h5 > /dev/null  # FFTW planning, kept as wisdom
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"

echo "| mode | alone (s) | together: first (s) | together: second (s) | worst / alone |"
echo "|---|--:|--:|--:|--:|"
for mode in ${MODES:-spinning passive}; do
  case "$mode" in
    spinning) export GOMP_SPINCOUNT=300000 ;;
    spin[0-9]*) export GOMP_SPINCOUNT="${mode#spin}" ;;
    passive) unset GOMP_SPINCOUNT ;;
    *) echo "unknown mode '$mode': allowed spinning, passive, spinN (N spins)" >&2; exit 2 ;;
  esac
  mapfile -t times < <(measure)
  worst="$(printf '%s\n' "${times[1]}" "${times[2]}" | sort -g | tail -1)"
  printf '| %s | %.2f | %.2f | %.2f | %.2f |\n' "$mode" "${times[0]}" "${times[1]}" "${times[2]}" \
    "$(echo "$worst / ${times[0]}" | bc -l)"
done
echo
echo "grid $grid (rough, periodic, pk-multilevel), $repeats rounds, medians; $(nproc) CPUs;" \
  "load average (1, 5, 15 min) before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg)"
