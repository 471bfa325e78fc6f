#!/usr/bin/env bash
# Gallery: a sphere on a coated half-space (docs/gallery.md#coated-sphere).
#   examples/gallery/coated_sphere.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 32x32 grid (CI).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
grid=128x128
[ "${QUICK:-0}" = 1 ] && grid=32x32
sphere=(--geometry sphere --radius 5e-3 --grid "$grid" --size 4e-4 --force 0.5)
# A rigid ball on a 20 um polymer layer (3 GPa) bonded to steel, and on
# the polymer alone: the hard substrate under the thin layer concentrates
# the pressure into a smaller, higher contact.
"$halfspace" solve "${sphere[@]}" --layer-thickness 20e-6 --layer-E 3e9 --layer-nu 0.35 \
  --substrate-E 2.1e11 --substrate-nu 0.29 --output "$out/coated.h5" --quiet
# E* of the polymer alone: E / (1 - nu^2) = 3 GPa / (1 - 0.35^2).
"$halfspace" solve "${sphere[@]}" --E-star 3.4188e9 --output "$out/polymer.h5" --quiet
"${PYTHON:-python3}" "$here/draw.py" coated "$out/coated.h5" "$out/polymer.h5" --out "$out/coated_sphere.png"
