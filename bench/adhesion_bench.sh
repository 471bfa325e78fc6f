#!/usr/bin/env bash
# The adhesive solver's cost against the elastic default on the same rough
# periodic surface and approaches, side by side (interleaved, so that a
# drifting machine load hits both alike). The surface is the headline's
# kind (self-affine, H = 0.8, 1 um cells, wavelengths down to 4 um, rms
# slope 0.1) on E* = 10 MPa, solved at approaches 400 and 500 nm as a
# two-step sweep (the second warm-started); adhesion Maugis-Dugdale,
# w = 0.05 J/m^2, h0 = 200 nm (docs/performance.md#adhesion).
# Usage: bench/adhesion_bench.sh [PROGRAM] [GRID] [REPEATS] [CASES]
#   PROGRAM  the halfspace executable [build/bin/halfspace]
#   GRID     cells per side [1024]
#   REPEATS  rounds; medians of the solve time are reported [3]
#   CASES    which solves, space separated, of: elastic adhesive-spg
#            adhesive-pcg [elastic adhesive-spg adhesive-pcg]; adhesive-pcg
#            is --adhesion-precondition on (preconditioned conjugate
#            gradients, the default), adhesive-spg off (spectral projected
#            gradients); both are given explicitly, so the script also runs
#            programs whose default differs
# Prints a Markdown table: iterations per step, the solver's own time per
# step (planning excluded; median over the rounds), the contact fraction
# and the time per step against the elastic solve.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
program="$(realpath "${1:-$root/build/bin/halfspace}")"
side="${2:-1024}"
repeats="${3:-3}"
cases="${4:-elastic adhesive-spg adhesive-pcg}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export HALFSPACE_FFTW_WISDOM="$work/wisdom"

size="$(awk -v n="$side" 'BEGIN { print n * 1e-6 }')"
"$program" generate --kind self-affine --grid "${side}x${side}" --size "$size" --hurst 0.8 --cutoff-short 4e-6 \
  --rms-slope 0.1 --seed 1 --output surface.h5 --quiet

# One sweep; $1 names the case, the rest are extra options. Prints
# "case step iterations seconds contact converged" for each step.
solve() {
  local name="$1"
  shift
  "$program" solve --height-map surface.h5 --boundary periodic --E-star 1e7 --approach=4e-7,5e-7 --threads 1 \
    --output "$name.h5" --quiet "$@" || true
  /usr/bin/python3 - "$name" <<'PY'
import sys, h5py
name = sys.argv[1]
with h5py.File(f"{name}.h5", "r") as f:
    s = f["sweep"]
    for k in range(len(s["iterations"])):
        print(name, k, int(s["iterations"][k]), float(s["seconds"][k]), float(s["contact_fraction"][k]),
              int(s["converged"][k]))
PY
}

adhesion=(--adhesion md --work-of-adhesion 0.05 --adhesion-range 2e-7)
solve warmup > /dev/null  # plans the transforms (kept as wisdom)
for ((k = 0; k < repeats; ++k)); do
  for c in $cases; do
    case "$c" in
      elastic) solve elastic ;;
      adhesive-spg) solve adhesive-spg "${adhesion[@]}" --adhesion-precondition off ;;
      adhesive-pcg) solve adhesive-pcg "${adhesion[@]}" --adhesion-precondition on ;;
      *) echo "unknown case $c" >&2; exit 2 ;;
    esac
  done
done > runs.txt

echo "| case (${side}^2, approaches 400, 500 nm) | iterations per step | solve time per step (median of $repeats) | contact | converged | time per step / elastic |"
echo "|---|--:|--:|--:|--:|--:|"
/usr/bin/python3 - <<'PY'
import statistics
rows = {}
for line in open("runs.txt"):
    name, step, it, t, contact, ok = line.split()
    rows.setdefault(name, {}).setdefault(int(step), []).append((int(it), float(t), float(contact), int(ok)))
def per_step(name):
    return [statistics.median(r[1] for r in runs) for _, runs in sorted(rows[name].items())]
elastic = per_step("elastic") if "elastic" in rows else None
for name, steps in rows.items():
    times = per_step(name)
    its = ", ".join(str(runs[0][0]) for _, runs in sorted(steps.items()))
    contact = ", ".join(f"{100 * runs[0][2]:.3f} %" for _, runs in sorted(steps.items()))
    ok = ", ".join("yes" if all(r[3] for r in runs) else "no" for _, runs in sorted(steps.items()))
    t = ", ".join(f"{x:.2f} s" for x in times)
    ratio = ", ".join(f"{x / e:.1f}" for x, e in zip(times, elastic)) if elastic else "-"
    print(f"| {name} | {its} | {t} | {contact} | {ok} | {ratio} |")
PY
