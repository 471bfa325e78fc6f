#!/usr/bin/env bash
# Gallery: the von Mises stress below a Hertz contact (docs/gallery.md#subsurface-von-mises).
#   examples/gallery/von_mises.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 32x32 grid, 8 depths (CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
grid=128x128
depths=1e-6:1.2e-4:40
if [ "${QUICK:-0}" = 1 ]; then
  grid=32x32
  depths=5e-6:1.2e-4:8
fi
# A steel sphere on steel, then the stresses at 40 depths down to 120 um
# (the largest von Mises stress of a Hertz contact lies near z = 0.48 a).
"$halfspace" solve --geometry sphere --radius 1e-2 --grid "$grid" --size 5e-4 --boundary free \
  --E1 2.1e11 --nu1 0.3 --E2 2.1e11 --nu2 0.3 --force 10 --output "$out/hertz.h5" --quiet
"$halfspace" stress "$out/hertz.h5" --depth-range "$depths" --nu 0.3 --output "$out/hertz_stress.h5" --quiet
"${PYTHON:-python3}" "$here/draw.py" von-mises "$out/hertz_stress.h5" --out "$out/von_mises.png"
# hertz_stress.xdmf: the volume in ParaView (paraview_screenshot.py draws it).
