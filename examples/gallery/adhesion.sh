#!/usr/bin/env bash
# Gallery: an adhesive sphere loaded and unloaded (docs/gallery.md#adhesion-loading-and-unloading).
#   examples/gallery/adhesion.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 32x32 grid, fewer steps (CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
grid=96x96
approach=-1.5e-6,-1e-6,-6e-7,-3e-7,0,5e-7,1e-6,2e-6,3e-6,2e-6,1e-6,5e-7,0,-3e-7,-6e-7,-1e-6,-1.5e-6,-2e-6,-2.5e-6
if [ "${QUICK:-0}" = 1 ]; then
  grid=32x32
  approach=-1e-6,0,1e-6,3e-6,1e-6,0,-1e-6,-2e-6
fi
# A soft sphere (E* = 1 MPa) with Maugis-Dugdale adhesion (w = 50 mJ/m^2,
# sigma0 = 100 kPa): in contact the surfaces stick, and on the way back
# the contact holds beyond its first touch, pulling (negative force).
"$halfspace" solve --geometry sphere --radius 1e-3 --grid "$grid" --size 2e-4 --E-star 1e6 \
  --adhesion md --work-of-adhesion 0.05 --adhesion-stress 1e5 \
  --approach="$approach" --output "$out/adhesion.h5" --quiet
"${PYTHON:-python3}" "$here/draw.py" adhesion "$out/adhesion.h5" --out "$out/adhesion.png"
