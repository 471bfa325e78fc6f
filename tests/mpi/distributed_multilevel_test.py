#!/usr/bin/env python3
"""The MPI program's pk-multilevel and load sweeps against the serial program
(HALFSPACE_MPI builds; ctest runs it).

usage: distributed_multilevel_test.py MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR

`mpiexec -np 1, 2 and 3 MPI_PROGRAM solve` with the default solver
(pk-multilevel) on periodic and free Hertz and rough contacts, single
solves and 3-step load sweeps, and with block deflation (pk-multilevel and
pk-fourier), must write the serial program's files: the same datasets,
shapes, types, storage (chunks, filters) and attributes (iteration counts,
coarse levels and their iterations included), floating-point data equal
within kTolerance of its largest value, contact sets identical; a sweep's
CSV likewise. The grids
make the multilevel's levels both distributed (with slab boundaries that do
not line up between levels on 3 processes) and gathered. A sweep that
cannot be written leaves nothing behind, and a 1024^2 sweep on 2 processes
peaks on the first within 25 % of the second (no whole field gathered).
"""
import csv
import os
import sys

import h5py
import numpy as np
from mpi_harness import Harness, kExitInputError

# Distributed reductions add in another order than the serial fixed blocks,
# and FFTW-MPI rounds differently from serial FFTW: equal to rounding.
kTolerance = 1e-12
# Values that record the run rather than the result (present in both, not
# compared): wall times, the program's path, the version with the build's
# git hash.
kRunValues = {"solve_seconds", "seconds", "command_line", "halfspace_version",
               "summary_csv_md5"}  # the CSV holds the steps' seconds
# Residuals are relative quantities near rounding at convergence: compared
# absolutely.
kAbsoluteValues = {"residual", "residual_history"}
kProcessCounts = (1, 2, 3)

harness = Harness(sys.argv)
mpi_program, serial_program, mpiexec, source_dir, work_dir = harness.arguments
fail = harness.fail


def close(name, got, want):
    """Whether float data `got` equals `want` within kTolerance; the error."""
    got = np.asarray(got, dtype=float)
    want = np.asarray(want, dtype=float)
    scale = 1.0 if name in kAbsoluteValues else max(float(np.max(np.abs(want))) if want.size else 0.0, 1e-300)
    error = float(np.max(np.abs(got - want))) / scale if want.size else 0.0
    return error <= kTolerance, error


def compare_attributes(where, got, want):
    harness.compare_attributes(where, got.attrs, want.attrs, kRunValues, kTolerance, kAbsoluteValues)


def compare_files(where, got_path, want_path):
    worst = 0.0
    with h5py.File(got_path, "r") as got, h5py.File(want_path, "r") as want:
        compare_attributes(where + " /", got, want)
        names = harness.same_objects(where, got, want)
        if names is None:
            return
        for name in names:
            compare_attributes(f"{where} /{name}", got[name], want[name])
            if not isinstance(want[name], h5py.Dataset):
                continue
            a, b = got[name], want[name]
            if a.shape != b.shape or a.dtype != b.dtype:
                fail(f"{where}: /{name} is {a.shape} {a.dtype}, serial {b.shape} {b.dtype}")
                continue
            storage = [(d.chunks, d.compression, d.compression_opts, d.shuffle) for d in (a, b)]
            if storage[0] != storage[1]:
                fail(f"{where}: /{name} is stored as {storage[0]} (chunks, filters), serial {storage[1]}")
            x, y = a[()], b[()]
            leaf = name.rsplit("/", 1)[-1]
            if leaf in kRunValues:
                continue
            if np.issubdtype(y.dtype, np.floating):
                ok, error = close(leaf, x, y)
                worst = max(worst, error) if leaf not in kAbsoluteValues else worst
                if not ok:
                    fail(f"{where}: /{name} differs by {error:.2e} (allowed {kTolerance:.0e})")
            elif not np.array_equal(x, y):
                fail(f"{where}: /{name} differs in {int(np.count_nonzero(x != y))} entries")
        # The contact set: pressure > 0 in every single solve and sweep step.
        for name in names:
            if name.rsplit("/", 1)[-1] == "pressure" and not np.array_equal(got[name][()] > 0, want[name][()] > 0):
                fail(f"{where}: the contact set of /{name} differs")
        iterations = want.attrs.get("iterations")
        print(f"{where}: largest field difference {worst:.2e} of the field's largest value; "
              f"iterations {got.attrs.get('iterations')} (serial {iterations}), coarse levels "
              f"{got.attrs.get('coarse_levels')}, coarse iterations {got.attrs.get('coarse_iterations')} "
              f"(serial {want.attrs.get('coarse_iterations')}), deflated iterations "
              f"{got.attrs.get('deflated_iterations')} (serial {want.attrs.get('deflated_iterations')})")


def compare_csv(where, got_path, want_path):
    with open(got_path, newline="") as g, open(want_path, newline="") as w:
        got, want = list(csv.DictReader(g)), list(csv.DictReader(w))
    if len(got) != len(want) or (want and list(got[0]) != list(want[0])):
        fail(f"{where}: the CSV's rows or columns differ from the serial one's")
        return
    for column in (want[0] if want else []):
        if column in kRunValues:
            continue
        ok, error = close(column, [float(r[column]) for r in got], [float(r[column]) for r in want])
        if not ok:
            fail(f"{where}: CSV column {column} differs by {error:.2e}")


def solve_case(name, arguments, process_counts=kProcessCounts, sweep=False, deflated=False):
    serial_output = harness.serial_output(name, "solve", arguments)
    if serial_output is None:
        return
    if deflated:
        with h5py.File(serial_output, "r") as want:
            if not want.attrs["deflated_iterations"] > 0:
                fail(f"{name}: the serial solve never applied the block deflation, so the case tests nothing of it")
    for where, output in harness.distributed_outputs(name, "solve", arguments, process_counts):
        compare_files(where, output, serial_output)
        if sweep:
            compare_csv(where, output[:-3] + ".csv", serial_output[:-3] + ".csv")


failure_case = harness.refusal_case


common = ["--E-star", "1e11", "--threads", "1", "--fft-planning", "estimate", "--quiet"]
# Hertz on a periodic 256 x 200 grid: levels 128 x 100 (distributed; on 3
# processes FFTW-MPI gives 67, 67, 66 fine rows but 34, 34, 32 coarse ones,
# so a coarse row's fine rows lie on the neighbour) and 64 x 50 (gathered).
hertz = ["--geometry", "sphere", "--radius", "0.01", "--grid", "256x200", "--size", "1e-3x0.78125e-3",
         "--boundary", "periodic", "--tol", "1e-12"] + common
solve_case("hertz-multilevel", hertz + ["--force", "5"])
# Rough: the self-affine 128 x 128 example (43, 43, 42 rows on 3 processes;
# its 64 x 64 level 22, 22, 20), under load and displacement control.
rough = ["--height-map", os.path.join(source_dir, "examples", "self_affine_128.h5"), "--boundary", "periodic",
         "--tol", "1e-12"] + common
solve_case("rough-multilevel-force", rough + ["--mean-pressure", "2e8"])
solve_case("rough-multilevel-approach", rough + ["--approach", "1e-6"])
# Free grids (the padded convolution): the same Hertz and rough cases.
free_hertz = [a if a != "periodic" else "free" for a in hertz]
solve_case("free-hertz-multilevel", free_hertz + ["--force", "5"])
free_rough = [a if a != "periodic" else "free" for a in rough]
solve_case("free-rough-multilevel-force", free_rough + ["--mean-pressure", "2e8"])
# Load sweeps: the second step warm-started, the third off by a factor 2
# (beyond the warm-start ratio 1.5), so started from the coarse levels again.
solve_case("rough-sweep-force", rough + ["--mean-pressure", "1e8,2e8,4e8"], sweep=True)
solve_case("hertz-sweep-approach", hertz + ["--approach", "2e-6,3e-6,3.5e-6"], sweep=True)

# Block deflation on a rough 512 x 352 surface under 1 GPa (21 % contact),
# where the correction joins in 11 (pk-multilevel) and 12 (pk-fourier)
# iterations: 32-row blocks straddle the slabs of 3 processes (118, 118 and
# 116 rows).
surface = os.path.join(work_dir, "rough-512x352.h5")
generated = harness.run([serial_program, "generate", "--kind", "self-affine", "--grid", "512x352", "--size",
                         "1e-3x0.6875e-3", "--hurst", "0.8", "--rms-slope", "0.1", "--seed", "3", "--output", surface,
                         "--quiet"])
if generated.returncode != 0:
    fail(f"generating the deflation case's surface failed: {generated.stderr.strip()}")
else:
    deflation_case = ["--height-map", surface, "--boundary", "periodic", "--mean-pressure", "1e9",
                      "--deflation-block", "32", "--tol", "1e-12"] + common
    solve_case("rough-multilevel-deflation", deflation_case, deflated=True)
    solve_case("rough-pk-fourier-deflation", deflation_case + ["--solver", "pk-fourier"], deflated=True)
    solve_case("free-rough-multilevel-deflation", [a if a != "periodic" else "free" for a in deflation_case],
               (2, 3), deflated=True)
    # Slabs thinner than a block (12 processes of about 30 rows): processes
    # that own no block row (none starts in their slab) hold only the halo
    # of the block row their rows lie in.
    solve_case("thin-slabs-pk-fourier-deflation", deflation_case + ["--solver", "pk-fourier"], (12,), deflated=True)
    # A sweep whose fields are chunked (180224 cells, above the 65536 stored
    # contiguously, in chunks of 118 rows): the slabs of 2 processes (176
    # rows) cut a chunk, those of 3 (118, 118, 116) match them.
    solve_case("rough-sweep-chunked", ["--height-map", surface, "--boundary", "periodic", "--mean-pressure",
                                       "5e8,1e9,2e9", "--tol", "1e-10"] + common, (2, 3), sweep=True)

missing = os.path.join(work_dir, "failure.h5")
for processes in (2, 3):
    failure_case("sweep with an invalid approach", processes, rough + ["--approach", "1e-7,1e-3"],
                 "mean initial gap", missing)

# A sweep that cannot be written: a missing directory (refused before the
# solve) and a file-size limit below the sweep file's size (32 KiB: `ulimit
# -f` counts 512-byte blocks in sh), met by the collective writer's
# reservation after the solves. Neither leaves the file, its CSV or a
# temporary behind. Open MPI's shared-memory transport maps files larger
# than the limit, so the processes talk over TCP there.
sweep_loads = ["--mean-pressure", "1e8,2e8,4e8"]
for processes in (2, 3):
    failure_case("sweep into a missing directory", processes, rough + sweep_loads, "does not exist",
                 os.path.join(work_dir, "no-such-directory", "sweep.h5"))
    limited = os.path.join(work_dir, "limited-sweep.h5")
    command = " ".join([mpi_program, "solve"] + rough + sweep_loads + ["--output", limited])
    result = harness.run([mpiexec, "--oversubscribe", "--mca", "btl", "self,tcp", "-np", str(processes), "sh", "-c",
                          "ulimit -f 64; exec " + command])
    where = f"sweep under a file-size limit, {processes} processes"
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    if result.returncode != kExitInputError:
        fail(f"{where}: exit {result.returncode}, expected {kExitInputError}; stderr: {result.stderr.strip()}")
    if len(errors) != 1 or "could not reserve" not in errors[0]:
        fail(f"{where}: expected one error line about the reservation, got {errors}")
    left = [f for f in os.listdir(work_dir) if f.startswith("limited-sweep")]
    if left:
        fail(f"{where}: left behind: {left}")
    print(f"{where}: {errors[0] if errors else result.stderr.strip()}")

# No process holds a sweep's whole fields: a 3-step sweep on a 1024^2 grid
# on 2 processes, each process's peak resident set measured by
# /usr/bin/time. Gathering the height map and the 3 steps' fields on the
# first process (as the sweep did before it was written collectively) put
# its peak far above the other's; now it must stay within 25 % of it.
if os.path.exists("/usr/bin/time"):
    peaks_dir = os.path.join(work_dir, "sweep-peaks")
    os.makedirs(peaks_dir, exist_ok=True)
    big_sweep = os.path.join(work_dir, "big-sweep.h5")
    command = " ".join([mpi_program, "solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "1024x1024",
                        "--size", "1e-3x1e-3", "--boundary", "periodic", "--approach", "2e-6,3e-6,3.5e-6",
                        "--tol", "1e-8", "--output", big_sweep] + common)
    result = harness.run([mpiexec, "--oversubscribe", "-np", "2", "sh", "-c",
                          f"exec /usr/bin/time -v -o {peaks_dir}/rank$OMPI_COMM_WORLD_RANK {command}"])
    where = "1024^2 sweep on 2 processes"
    if result.returncode != 0:
        fail(f"{where}: exit {result.returncode}: {result.stderr.strip()}")
    else:
        peaks = []
        for rank in (0, 1):
            with open(os.path.join(peaks_dir, f"rank{rank}")) as report:
                peaks += [int(line.split(":")[1]) for line in report if "Maximum resident set size" in line]
        if len(peaks) != 2:
            fail(f"{where}: could not read both processes' peaks: {peaks}")
        elif peaks[0] > 1.25 * peaks[1]:
            fail(f"{where}: the first process peaked at {peaks[0] / 1024:.0f} MiB, "
                 f"more than 25 % above the second's {peaks[1] / 1024:.0f} MiB")
        else:
            print(f"{where}: peaks {peaks[0] / 1024:.0f} MiB (first) and {peaks[1] / 1024:.0f} MiB")
    for path in (big_sweep, big_sweep[:-3] + ".csv"):
        if os.path.exists(path):
            os.remove(path)

harness.finish()
print("all distributed multilevel solves and sweeps match the serial program")
