#!/usr/bin/env bash
# Gallery: a measured height map to a contact map (docs/gallery.md#measured-map-to-contact-map).
#   examples/gallery/measured_contact.sh [OUT_DIR]
# HALFSPACE: the program [halfspace]; QUICK=1: a 64x64 window (CI).
# The map is ../shared/data/topography/KautschukInfiniteFocus.h5 beside the
# project root (or under $SHARED): a rubber surface measured by focus
# variation, 857x631 points 2.28 um apart. Without it, the 56x40 crop of the
# original .x3p in tests/data.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${1:-.}"
mkdir -p "$out"
halfspace="${HALFSPACE:-halfspace}"
map="${SHARED:-$here/../../../shared}/data/topography/KautschukInfiniteFocus.h5"
window=(--window 0,0,256,256)
[ "${QUICK:-0}" = 1 ] && window=(--window 0,0,64,64)
if [ ! -f "$map" ]; then
  map="$here/../../tests/data/kautschuk-crop-40x56.x3p"
  window=()
fi
# The instrument left a few points invalid: fill them; the map is tilted:
# remove the best plane. Then press a flat elastic body (E* = 10 MPa, a
# rubber) onto it at 100 kPa. The map does not repeat: a free boundary.
"$halfspace" solve --height-map "$map" --invalid fill "${window[@]}" --detrend plane --boundary free \
  --E-star 1e7 --mean-pressure 1e5 --output "$out/measured.h5" --plot --quiet
# measured_maps.png: height, pressure and contact maps; measured.xdmf opens in ParaView.
