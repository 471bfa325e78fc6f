#!/usr/bin/env bash
# Builds halfspace_bench (Release) and runs it: machine, commit and table appended to
# bench/results/<date>-<shortcommit>.txt, the JSON to a new file beside it. A first
# argument --large adds the large grids (periodic 2048^2 and 4096^2, free 1024^2 and
# 2048^2; most of an hour); other arguments go to halfspace_bench (e.g.
# --benchmark_filter=...).
set -euo pipefail
if [[ "${1:-}" == "--large" ]]; then
  export HALFSPACE_BENCH_LARGE=1
  shift
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_BENCH_BUILD_DIR:-$root/build-bench}"

# A fresh benchmark build skips the tests; an existing build directory (say
# the main one, via HALFSPACE_BENCH_BUILD_DIR) keeps its own choice.
if [[ -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
else
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFSPACE_BUILD_TESTS=OFF >/dev/null
fi
cmake --build "$build" -j "$(nproc)" --target halfspace_bench

date="$(date -u +%Y-%m-%d)"
commit="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
results="$root/bench/results"
mkdir -p "$results"
text="$results/$date-$commit.txt"
# One JSON per run, never reused: the time of day, plus a counter if two runs
# start in the same second.
json="$results/$date-$commit-$(date -u +%H%M%S).json"
suffix=1
while [[ -e "$json" ]]; do
  json="$results/$date-$commit-$(date -u +%H%M%S)-$suffix.json"
  suffix=$((suffix + 1))
done

cpu_model="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//' || true)"
{
  echo "================================================================"
  echo "date:     $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "commit:   $(git -C "$root" describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)"
  echo "machine:  $(uname -srm), nproc $(nproc), cpu ${cpu_model:-unknown}"
  echo "load:     $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) before the run"
  echo "command:  scripts/bench.sh ${HALFSPACE_BENCH_LARGE:+--large }$*"
  echo "json:     bench/results/$(basename "$json")"
  echo
} | tee -a "$text"

# Busy CPU time of the whole machine (/proc/stat, in clock ticks) and of this
# shell's finished children (bash `times`): their difference over the run is
# what other processes took while the benchmark ran.
machine_busy_ticks() { awk '/^cpu /{print $2 + $3 + $4 + $7 + $8 + $9}' /proc/stat; }
times_file="$(mktemp)"
trap 'rm -f "$times_file"' EXIT
# Sets children_cpu (user + system seconds). `times` runs in this shell: in a
# $(...) subshell it would not see this shell's children.
measure_children_cpu() {
  times >"$times_file"
  children_cpu="$(tail -n 1 "$times_file" |
    awk '{ n = 0; for (i = 1; i <= 2; i++) { split($i, t, /[ms]/); n += 60 * t[1] + t[2] } print n }')"
}
ticks_per_second="$(getconf CLK_TCK)"
busy_before="$(machine_busy_ticks)"
measure_children_cpu
own_before="$children_cpu"
wall_before="$(date +%s.%N)"

# Flags given to this script come after the defaults, so they win. Three
# repetitions, because on this 2-vCPU virtual machine two-thread timings move
# by up to 1.5x between minutes; the table shows their mean, median, stddev
# and cv, the JSON every repetition. No default filter: the full set takes
# about 7 minutes on 2 quiet cores (--benchmark_repetitions=1: about 2.5).
"$build/bench/halfspace_bench" \
  --benchmark_out="$json" --benchmark_out_format=json \
  --benchmark_repetitions=3 --benchmark_display_aggregates_only=true \
  --benchmark_counters_tabular=true --benchmark_color=false \
  "$@" 2>&1 | tee -a "$text"

busy_after="$(machine_busy_ticks)"
measure_children_cpu
own_after="$children_cpu"
wall_after="$(date +%s.%N)"
{
  echo
  echo "load:     $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the run (includes the run itself)"
  awk -v b0="$busy_before" -v b1="$busy_after" -v hz="$ticks_per_second" -v o0="$own_before" -v o1="$own_after" \
    -v w0="$wall_before" -v w1="$wall_after" -v cores="$(nproc)" 'BEGIN {
      wall = w1 - w0; busy = (b1 - b0) / hz; own = o1 - o0; other = busy - own; if (other < 0) other = 0
      printf "cpu:      %.1f s wall; benchmark %.1f CPU-s, other processes %.1f CPU-s (%.0f%% of %d cores)\n",
             wall, own, other, 100 * other / (wall * cores), cores }'
} | tee -a "$text"
