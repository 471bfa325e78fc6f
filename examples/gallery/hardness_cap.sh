#!/usr/bin/env bash
# Gallery: a hardness cap on a Hertz sphere (docs/gallery.md#hardness-cap).
#   examples/gallery/hardness_cap.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 32x32 grid (CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
grid=128x128
[ "${QUICK:-0}" = 1 ] && grid=32x32
sphere=(--geometry sphere --radius 5e-3 --grid "$grid" --size 6e-4 --boundary free --E-star 1e11 --force 20)
# The same sphere and force, elastic and with the pressure capped at a
# hardness of 0.8 GPa (elastic-perfectly plastic cells: docs/theory.md#hardness-cap).
"$halfspace" solve "${sphere[@]}" --output "$out/elastic.h5" --quiet
"$halfspace" solve "${sphere[@]}" --hardness 8e8 --output "$out/capped.h5" --quiet
"${PYTHON:-python3}" "$here/draw.py" hardness "$out/elastic.h5" "$out/capped.h5" --out "$out/hardness_cap.png"
