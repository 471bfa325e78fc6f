#!/usr/bin/env bash
# The hardness cap's cost: the same rough periodic surface and load solved
# elastic and capped, side by side (interleaved, so that a drifting machine
# load hits both alike). The surface is the headline's (self-affine, H = 0.8,
# 1 um cells, wavelengths down to 4 um, rms slope 0.1), under 4 MPa on
# E* = 1 GPa; the caps are 20 MPa and 100 MPa (H / E* = 0.02 and 0.1).
# Usage: bench/hardness_bench.sh [PROGRAM] [GRID] [REPEATS] [SOLVER]
#   PROGRAM  the halfspace executable [build/bin/halfspace]
#   GRID     cells per side [1024]
#   REPEATS  rounds; medians of the solve time are reported [3]
#   SOLVER   [pk-multilevel]
# Prints a Markdown table: iterations, K and M^-1 products, solve time
# (the solver's own, planning excluded), plastic and contact fraction.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build/bin/halfspace}")"
side="${2:-1024}"
repeats="${3:-3}"
solver="${4:-pk-multilevel}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export HALFSPACE_FFTW_WISDOM="$work/wisdom"

size="$(awk -v n="$side" 'BEGIN { print n * 1e-6 }')"
"$program" generate --kind self-affine --grid "${side}x${side}" --size "$size" --hurst 0.8 --cutoff-short 4e-6 \
  --rms-slope 0.1 --seed 1 --output surface.h5 --quiet

# One solve; $1 names the case, the rest are extra options. Prints
# "case iterations K M solve_seconds plastic contact".
solve() {
  local name="$1"
  shift
  "$program" solve --height-map surface.h5 --boundary periodic --E-star 1e9 --mean-pressure 4e6 \
    --solver "$solver" --output "$name.h5" --quiet "$@"
  /usr/bin/python3 - "$name" <<'PY'
import sys, h5py
name = sys.argv[1]
with h5py.File(f"{name}.h5", "r") as f:
    a = f.attrs
    print(name, int(a["iterations"]), int(a["operator_applications"]), int(a["preconditioner_applications"]),
          float(a["solve_seconds"]), float(a["plastic_fraction"]), float(a["contact_fraction"]))
PY
}

solve warmup > /dev/null  # plans the transforms (kept as wisdom)
for ((k = 0; k < repeats; ++k)); do
  solve elastic
  solve cap-20MPa --hardness 2e7
  solve cap-100MPa --hardness 1e8
done > runs.txt

echo "| case ($solver, ${side}^2, 4 MPa) | iterations | K | M^-1 | solve time (median of $repeats) | plastic | contact | time / elastic |"
echo "|---|--:|--:|--:|--:|--:|--:|--:|"
/usr/bin/python3 - <<'PY'
import statistics
rows = {}
for line in open("runs.txt"):
    name, it, k, m, t, plastic, contact = line.split()
    rows.setdefault(name, []).append((int(it), int(k), int(m), float(t), float(plastic), float(contact)))
elastic = statistics.median(r[3] for r in rows["elastic"])
for name, runs in rows.items():
    t = statistics.median(r[3] for r in runs)
    it, k, m, _, plastic, contact = runs[0]
    print(f"| {name} | {it} | {k} | {m} | {t:.2f} s | {plastic:.3f} | {contact:.3f} | {t / elastic:.2f} |")
PY
