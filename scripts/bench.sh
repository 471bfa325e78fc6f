#!/usr/bin/env bash
# Builds halfspace_bench (Release) and runs it. Appends machine, commit and the
# text table to bench/results/<date>-<shortcommit>.txt; the JSON goes to a new
# file beside it. Extra arguments go to halfspace_bench (e.g. --benchmark_filter=...).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_BENCH_BUILD_DIR:-$root/build-bench}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFSPACE_BUILD_TESTS=OFF >/dev/null
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
  echo "command:  scripts/bench.sh $*"
  echo "json:     bench/results/$(basename "$json")"
  echo
} | tee -a "$text"

# The flags after the defaults win, so a caller's --benchmark_filter replaces
# none of ours (there is no default filter: the full set runs in ~5 minutes
# on 2 quiet cores).
"$build/bench/halfspace_bench" \
  --benchmark_out="$json" --benchmark_out_format=json \
  --benchmark_counters_tabular=true --benchmark_color=false \
  "$@" 2>&1 | tee -a "$text"

echo | tee -a "$text"
echo "load:     $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the run" | tee -a "$text"
