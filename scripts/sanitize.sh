#!/usr/bin/env bash
# Builds the library and tests with AddressSanitizer and UndefinedBehaviour-
# Sanitizer (Debug, -O1) into ./build-sanitize and runs the whole test suite
# under them: any invalid access, leak or undefined behaviour fails the test
# it happens in. Installs what is missing first. Leaks inside Siconos are suppressed
# (scripts/lsan-suppressions.txt says why). Extra arguments go to ctest,
# e.g. scripts/sanitize.sh -R Lemke. Takes about 15 minutes on 2 cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
"$root/scripts/install-deps.sh"
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
cmake --build "$build" -j "$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan-suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
ctest -j "$(nproc)" --output-on-failure "$@"
