#!/usr/bin/env bash
# Iterations of the default solver on a growing domain, several surfaces per
# size: the per-size counts and means, a logarithmic fit and the increase per
# doubling, printed and appended to
# bench/results/<date>-<shortcommit>-growing-domain.md. Builds halfspace
# (Release, build-bench), then runs bench/headline/growing_domain.py; arguments go to
# it, options for `halfspace solve` after --, e.g.
#
#   scripts/growing-domain.sh --sizes 256,512,1024 --seeds 1,2,3 -- --deflation-block 0
#
# The defaults (256^2 to 4096^2, 5 seeds, --deflation-block 32) take about
# ten minutes on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_BENCH_BUILD_DIR:-$root/build-bench}"
python="${HALFSPACE_PYTHON:-/usr/bin/python3}"

"$python" -c 'import h5py' 2>/dev/null || {
  echo "growing-domain: error: $python cannot import h5py: install python3-h5py (scripts/install-deps.sh) or set HALFSPACE_PYTHON" >&2
  exit 1
}

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHALFSPACE_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target halfspace_cli

exec "$python" "$root/bench/headline/growing_domain.py" --build-dir "$build" "$@"
