#!/usr/bin/env bash
# The main job: install what is missing, build, and solve a demo contact
# (a Hertz sphere on a 256x256 free-boundary grid) into demo/hertz_sphere.h5.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
mkdir -p "$root/demo"
"${HALFSPACE_BUILD_DIR:-$root/build}/bin/halfspace" solve \
  --geometry sphere --radius 0.01 --grid 256x256 --size 0.6e-3x0.6e-3 --boundary free \
  --E1 210e9 --nu1 0.3 --E2 210e9 --nu2 0.3 --force 50 \
  --output "$root/demo/hertz_sphere.h5"
