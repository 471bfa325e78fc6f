#!/bin/sh
# halfspace against Tamaas (bench/compare_tamaas.py). Tamaas is never a
# dependency of halfspace: it is installed from PyPI into a virtual
# environment in the build directory, and where that fails (no network, no
# wheel for this platform) the comparison is skipped with a message, exit 0.
#
#   scripts/compare-tamaas.sh [BUILD_DIR] [compare_tamaas.py options...]
#   scripts/compare-tamaas.sh build --sizes 256 512 1024 2048
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
[ $# -gt 0 ] && shift
exe="$build/bin/halfspace"
[ -x "$exe" ] || { echo "error: $exe not found: build halfspace first (scripts/build.sh)" >&2; exit 1; }

venv="$build/tamaas-venv"
python=${HALFSPACE_PYTHON:-/usr/bin/python3}
if [ ! -x "$venv/bin/python" ]; then
  # A venv of its own: Tamaas's wheels want a newer numpy than Debian's, and
  # Debian's h5py is built against Debian's numpy, so all three come from PyPI.
  if ! "$python" -m venv "$venv" >/dev/null 2>&1; then
    echo "compare-tamaas: skipped, '$python -m venv' failed (install python3-venv)"
    rm -rf "$venv"
    exit 0
  fi
fi
if ! "$venv/bin/python" -c 'import tamaas, h5py, numpy' 2>/dev/null; then
  if ! "$venv/bin/pip" install --quiet tamaas h5py numpy; then
    echo "compare-tamaas: skipped, 'pip install tamaas h5py numpy' failed (offline, or no wheel for this platform)"
    exit 0
  fi
fi
exec "$venv/bin/python" "$here/bench/compare_tamaas.py" --halfspace "$exe" "$@"
