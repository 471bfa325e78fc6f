#!/usr/bin/env bash
# The headline table: whole solves (iterations, K and M^-1 products, seconds,
# seconds per iteration over the bare FFT pair, peak memory) for periodic rough
# surfaces and free-boundary Hertz, printed and appended to
# bench/results/<date>-<shortcommit>-headline.md. Builds halfspace and
# fft_floor (Release, build-bench like scripts/bench.sh), then runs
# bench/headline/headline.py; arguments go to it, e.g.
#
#   scripts/headline.sh --periodic-sizes 256,512 --free-sizes 128 --threads 1,2
#
# Python: $HALFSPACE_PYTHON, else /usr/bin/python3 (Debian's, with h5py; a
# python3 earlier on PATH may lack it). The defaults take tens of minutes on
# 2 cores; --skip-slow leaves out plain pk on the largest grids.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_BENCH_BUILD_DIR:-$root/build-bench}"
python="${HALFSPACE_PYTHON:-/usr/bin/python3}"

[[ -x /usr/bin/time ]] || {
  echo "headline: error: /usr/bin/time not found: install GNU time (Debian package 'time', scripts/install-deps.sh)" >&2
  exit 1
}
"$python" -c 'import h5py' 2>/dev/null || {
  echo "headline: error: $python cannot import h5py: install python3-h5py (scripts/install-deps.sh) or set HALFSPACE_PYTHON" >&2
  exit 1
}

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFSPACE_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target halfspace_cli fft_floor

# The build directory comes first so that a --build-dir given here wins.
exec "$python" "$root/bench/headline/headline.py" --build-dir "$build" "$@"
