#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang with ASan and UBSan, a build
# of its own) and runs each for SECONDS (default 300) on one core, starting
# from the seed corpus in fuzz/corpus/<reader>/. Prints, per harness, the
# executions per second and the coverage reached (libFuzzer's cov: and ft:).
# Inputs that crash are written to $HALFSPACE_FUZZ_DIR/crashes/<reader>/ and
# make the script fail. New corpus entries go to $HALFSPACE_FUZZ_DIR/corpus/,
# not into the repository.
# HALFSPACE_FUZZ_SEED fixes libFuzzer's seed (scripts/test.sh sets it, so a
# short run in CI repeats the run checked before committing); unset, each
# run explores from a new random seed.
#   scripts/fuzz.sh [SECONDS] [harness ...]     harnesses: hdf5 npy text_matrix profile x3p gsf result toml_config
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-300}"
shift || true
harnesses=("$@")
if [ "${#harnesses[@]}" -eq 0 ]; then
  harnesses=(hdf5 npy text_matrix profile x3p gsf result toml_config)
fi
build="${HALFSPACE_FUZZ_BUILD_DIR:-$root/build-fuzz}"
work="${HALFSPACE_FUZZ_DIR:-$build/runs}"
cc="${CC_FUZZ:-clang-14}"
cxx="${CXX_FUZZ:-clang++-14}"

cmake -S "$root/fuzz" -B "$build" -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build "$build" -j "$(nproc)" >/dev/null

# Memory: the readers must refuse what they cannot hold, so a single input
# costing more than 2 GiB of real memory is a failure (-rss_limit_mb), and so is a
# single allocation above 1 GiB (-malloc_limit_mb) in our own readers. An
# allocation the system cannot give returns NULL, as glibc's malloc does in
# the program (allocator_may_return_null=1), so the library's handling of it
# is what is tested. One exception: libhdf5 reserves metadata buffers of the
# sizes a damaged file declares before it reads them (a 140-byte file asks
# for 4-40 GiB; the test AMetadataEntryTooLargeToAllocateIsAFileError holds
# one). Such a reservation in an object header is never touched (the
# program's peak on such files: 23 MB) and the open fails with a FileError;
# the superblock's own fields, whose reservations libhdf5 does fill, are
# checked first (src/io/hdf5_superblock.cpp). So the HDF5 harnesses (hdf5,
# result) have no per-allocation limit of libFuzzer's, only the limit on
# real memory; and since ASan would map shadow memory for such a
# reservation (1/8 of it: 2.6 GB for a 21 GiB object header, found by the
# result harness, while the program's peak on that file is 22 MB), a
# single allocation above 2 GiB returns NULL there, as the system may
# refuse it too (libhdf5 then fails the open). Filled reservations below
# that still count against the real-memory limit.
malloc_limit_mb() {
  if [ "$1" = hdf5 ] || [ "$1" = result ]; then echo 1048576; else echo 1024; fi
}
asan_options() {
  local common=detect_leaks=1:allocator_may_return_null=1
  if [ "$1" = hdf5 ] || [ "$1" = result ]; then echo "$common:max_allocation_size_mb=2048"; else echo "$common"; fi
}
seed_flag=()
if [ -n "${HALFSPACE_FUZZ_SEED:-}" ]; then seed_flag=(-seed="$HALFSPACE_FUZZ_SEED"); fi
status=0
printf '%-12s %10s %8s %8s %8s  %s\n' harness "exec/s" cov ft corpus result
for h in "${harnesses[@]}"; do
  corpus="$work/corpus/$h"
  crashes="$work/crashes/$h"
  mkdir -p "$corpus" "$crashes"
  log="$work/$h.log"
  set +e
  ASAN_OPTIONS="$(asan_options "$h")" \
    LSAN_OPTIONS="suppressions=$root/fuzz/lsan-suppressions.txt:print_suppressions=0" \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz_$h" "$corpus" "$root/fuzz/corpus/$h" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -malloc_limit_mb="$(malloc_limit_mb "$h")" -max_len=65536 -timeout=10 -print_final_stats=1 -artifact_prefix="$crashes/" "${seed_flag[@]}" \
    >"$log" 2>&1
  rc=$?
  set -e
  # The last status line: "#N DONE cov: C ft: F corp: K/..." and the final stats.
  line="$(grep -E '^#[0-9]+' "$log" | tail -1 || true)"
  cov="$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$line")"
  ft="$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$line")"
  corp="$(sed -nE 's/.* corp: ([0-9]+).*/\1/p' <<<"$line")"
  execs="$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$log" | tail -1)"
  result=ok
  if [ "$rc" -ne 0 ]; then
    result="FAILED (exit $rc; see $log and $crashes)"
    status=1
  fi
  printf '%-12s %10s %8s %8s %8s  %s\n' "$h" "${execs:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$result"
done
exit "$status"
