#!/usr/bin/env bash
# A Stribeck curve on a measured surface (docs/usage.md#a-stribeck-curve-on-a-measured-profile):
# a steel roller (R = 0.5 mm, E* = 113 GPa) on a flat whose profile is a
# stylus scan, lubricated by a mineral oil (eta0 = 0.04 Pa s, Roelands with
# alpha = 2.27e-8 1/Pa, limiting shear stress 0.05 p), at 2 kN/m (Hertz
# half-width 4.7 um, 270 MPa) and 20 % slide-to-roll, swept from 3 m/s down
# to 30 um/s: full film, mixed, boundary (Coulomb mu = 0.1 on contacts).
#   examples/stribeck_measured.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: five speeds (CI); NO_PLOT=1:
# no figures (they need python3 with matplotlib and h5py, as --plot does).
# The profile is ../shared/data/topography/dektak-1.h5 beside the project
# root (or under $SHARED): a Bruker Dektak line scan, 9600 points 0.156 um
# apart. Without it, the original Dektak export tests/data/dektak-1.csv (the
# same scan). The mixed film is a line contact on the dense path (at most
# 2048 points): a 240-point window (37.5 um, about 8 Hertz half-widths) of
# the scan at its own spacing, its tilt removed, under a cylinder of the same
# points (the roller's shape, added by --roughness).
# Writes stribeck.csv (one line per speed), last.h5 (the film at the
# slowest speed) and, with --plot, stribeck_stribeck.png and last_film.png.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
profile="${SHARED:-$here/../../shared}/data/topography/dektak-1.h5"
if [ ! -f "$profile" ]; then
  profile="$here/../tests/data/dektak-1.csv"
fi
if [ ! -f "$profile" ]; then
  echo "stribeck_measured.sh: skipped: neither ../shared/data/topography/dektak-1.h5 nor tests/data/dektak-1.csv" >&2
  exit 0
fi
speeds=3,1,0.3,0.1,0.03,0.01,0.003,0.001,0.0007,0.0005,0.0004,0.0003,0.0002,0.0001,0.00003
if [ "${QUICK:-0}" = 1 ]; then
  speeds=1,0.01,0.001,0.0007,0.0001
fi
plot=(--plot)
if [ "${NO_PLOT:-0}" = 1 ]; then
  plot=()
fi
# The roller: 240 points over 240 x 0.15625 um, the scan's own spacing.
"$halfspace" generate --kind cylinder --grid 240 --size 3.75e-5 --radius 5e-4 --output "$out/roller.h5" --quiet
"$halfspace" lubricate --height-map "$profile" --window 3000,240 --detrend plane --roughness "$out/roller.h5" \
  --mixed --E-star 1.13e11 --force 2e3 --viscosity 0.04 --pressure-viscosity 2.27e-8 --piezoviscosity roelands \
  --limiting-shear-slope 0.05 --contact-friction 0.1 --entrainment-velocity 1 --sliding-velocity 0.2 \
  --speeds "$speeds" --stribeck "$out/stribeck.csv" --output "$out/last.h5" "${plot[@]}" --quiet
# The curve: speed, Hersey number, friction coefficient, contact share, central film.
awk -F, 'NR == 1 { printf "%10s %10s %8s %8s %12s\n", "U (m/s)", "Hersey", "mu", "contact", "h_c (m)"; next }
         { printf "%10.3g %10.3g %8.4f %8.3f %12.3g %s\n", $1, $2, $3, $6, $8, ($10 == "converged" ? "" : $10) }' \
  "$out/stribeck.csv"
