#!/usr/bin/env bash
# Gallery: a load sweep and the contact area against the load (docs/gallery.md#load-sweep).
#   examples/gallery/load_sweep.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 32x32 grid (CI).
set -euo pipefail
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
grid=256x256
[ "${QUICK:-0}" = 1 ] && grid=32x32
# A periodic self-affine surface (H = 0.8, rms slope 0.1) ...
"$halfspace" generate --kind self-affine --grid "$grid" --size 1e-3x1e-3 --rms-slope 0.1 --seed 1 \
  --output "$out/rough.h5" --quiet
# ... pressed at twelve mean pressures from 0.1 to 20 MPa, log-spaced; each
# step starts from the previous one's pressure.
"$halfspace" solve --height-map "$out/rough.h5" --boundary periodic --E-star 1e9 \
  --mean-pressure 1e5:2e7:12 --output "$out/sweep.h5" --plot --quiet
# sweep_sweep.png: contact fraction and mean gap against the mean pressure;
# sweep.csv: the table; sweep.xdmf: every step in ParaView (time = step).
