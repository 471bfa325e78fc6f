#!/usr/bin/env bash
# Iterations per tangential step and time against the normal solve of the
# same rough periodic contact (bench/tangential_bench.cpp), one process per
# grid size (so the peak memory is that size's), REPEATS runs each; prints a
# Markdown table of the medians.
# Usage: bench/tangential_bench.sh [BENCH] [SIZES] [REPEATS] [METHOD]
#   BENCH    the Google Benchmark program [build/bench/halfspace_bench]
#   SIZES    comma-separated cells per side [256,512,1024] (2048 and 4096
#            need HALFSPACE_BENCH_LARGE=1, set here when asked for)
#   REPEATS  runs per size [3]
#   METHOD   conjugate_gradient or projected_gradient [conjugate_gradient]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build/bench/halfspace_bench}")"
sizes="${2:-256,512,1024}"
repeats="${3:-3}"
method="${4:-conjugate_gradient}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export HALFSPACE_BENCH_LARGE=1
for n in ${sizes//,/ }; do
  "$program" --benchmark_filter="BM_TangentialStep/$method/$n/" --benchmark_repetitions="$repeats" \
    --benchmark_format=json >"$work/$n.json" 2>"$work/$n.err" || { cat "$work/$n.err" >&2; exit 1; }
done
python3 - "$work" "$sizes" "$method" <<'PY'
import json, statistics, sys
work, sizes, method = sys.argv[1], sys.argv[2].split(","), sys.argv[3]
print(f"method {method}; medians of the runs; times in s")
print("| grid | contact | normal iterations (pk-multilevel / pk-fourier) | tangential iterations (step 1 / step 2) "
      "| normal s | step 1 s | step 1 / normal | step 2 / normal | step 1 / pk-fourier | peak B/point | friction B/point "
      "| converged |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for n in sizes:
    runs = [b for b in json.load(open(f"{work}/{n}.json"))["benchmarks"] if b.get("run_type") == "iteration"]
    med = lambda key: statistics.median(r[key] for r in runs)
    print(f"| {n}^2 | {med('contact_fraction'):.3f} | {med('normal_iterations'):.0f} / {med('fourier_iterations'):.0f} "
          f"| {med('first_iterations'):.0f} / {med('second_iterations'):.0f} | {med('normal_s'):.3g} "
          f"| {med('first_s'):.3g} | {med('first_over_normal'):.2f} | {med('second_over_normal'):.2f} "
          f"| {med('first_over_fourier'):.2f} | {max(r['peak_B_per_point'] for r in runs):.0f} "
          f"| {max(r['friction_B_per_point'] for r in runs):.0f} "
          f"| {min(r['converged'] for r in runs):.0f} |")
PY
