#!/usr/bin/env bash
# A fretting loop on a measured surface (docs/usage.md#friction): a rubber
# block (E = 10 MPa, nu = 0.5) pressed onto the rigid, rough surface of a
# measured map, then sheared back and forth below sliding, mu = 0.8.
#   examples/fretting_loop.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 64x64 window (CI).
# The map is ../shared/data/topography/KautschukInfiniteFocus.h5 beside the
# project root (or under $SHARED): a rubber surface measured by focus
# variation, 857x631 points 2.28 um apart. Without it, the 56x40 crop of the
# original .x3p in tests/data.
#
# Friction needs each body's E and nu, and elastically similar bodies
# (Dundurs' beta = 0): an incompressible body on a rigid one (--E2 inf) is.
# The loop: load to Q* = 0.5 mu P in 4 steps, down to -Q* and back up in 8
# steps a branch; each step starts from the state the previous one left.
# Writes loop.h5 (the normal contact, one group per step), loop.csv (step,
# Q_x, Q_y, delta_x, delta_y, stick_fraction, dissipated_energy), and with
# --plot loop_maps.png and loop_friction.png (the loop, Q_x against delta_x,
# and the stick/slip map of the last step).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
map="${SHARED:-$here/../../shared}/data/topography/KautschukInfiniteFocus.h5"
# Normal forces of about 100 kPa mean pressure over each window.
window=(--window 0,0,256,256)
force=0.034
if [ "${QUICK:-0}" = 1 ]; then
  window=(--window 0,0,64,64)
  force=0.0021
fi
if [ ! -f "$map" ]; then
  map="$here/../tests/data/kautschuk-crop-40x56.x3p"
  window=()
  force=0.0012
fi
mu=0.8
amplitude=$(awk -v mu="$mu" -v p="$force" 'BEGIN { printf "%.6g", 0.5 * mu * p }')
loop="0:${amplitude}:5;${amplitude}:-${amplitude}:9;-${amplitude}:${amplitude}:9"
# The instrument left a few points invalid: fill them; the map is tilted:
# remove the best plane. The map does not repeat: a free boundary.
"$halfspace" solve --height-map "$map" --invalid fill "${window[@]}" --detrend plane --boundary free \
  --E1 1e7 --nu1 0.5 --E2 inf --nu2 0.3 --force "$force" \
  --friction "$mu" --tangential-force "$loop" --output "$out/loop.h5" --plot --quiet
# The energy dissipated over the closed cycle (steps 5 to 22), from the CSV.
awk -F, 'NR > 1 && $1 >= 5 { w += $7 } END { printf "energy dissipated per cycle: %.4g J\n", w }' "$out/loop.csv"
