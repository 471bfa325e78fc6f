#!/bin/sh
# The full robustness matrix of the interface laws (bench/robustness_matrix.py):
# every 2D measured map of ../shared/data/topography beside the project root
# (or $SHARED) in its central 256 x 256 window, periodic and free, each law
# at three loads; about 400 solves, at low priority and two at a time.
# Writes the Markdown table (docs/validation.md#robustness-matrix is one) and
# exits 1 if any run FAILED.
#
#   scripts/robustness-matrix.sh [BUILD_DIR] [OUTPUT.md] [robustness_matrix.py options...]
#   scripts/robustness-matrix.sh build matrix.md --window 128 --laws md-force,md-approach
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
[ $# -gt 0 ] && shift
output=${1:-robustness-matrix.md}
[ $# -gt 0 ] && shift
exe="$build/bin/halfspace"
[ -x "$exe" ] || { echo "error: $exe not found: build halfspace first (scripts/build.sh)" >&2; exit 1; }
exec nice -n 10 "${HALFSPACE_PYTHON:-/usr/bin/python3}" "$here/bench/robustness_matrix.py" --halfspace "$exe" \
  --jobs 2 --threads 1 --markdown "$output" "$@"
