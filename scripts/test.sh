#!/usr/bin/env bash
# Install what is missing, build, and run the whole test suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
ctest --test-dir "${HALFSPACE_BUILD_DIR:-$root/build}" --output-on-failure -j "$(nproc)"
