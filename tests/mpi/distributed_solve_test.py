#!/usr/bin/env python3
"""The MPI program against the serial one (HALFSPACE_MPI builds; ctest runs it).

usage: distributed_solve_test.py MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR

For Hertz and rough contacts on periodic and free (non-periodic) grids,
`mpiexec -np 1, 2 and 3 MPI_PROGRAM solve` (3 gives uneven slabs) must write
the serial program's file: the same
datasets, shapes, types and attributes, fields equal within kFieldTolerance
of their largest value, the contact set identical; with --stress-depths the
/stress group too, and `mpiexec -np 1, 2, 3 MPI_PROGRAM stress` the serial
stress command's file. Failures (a bad file,
which only the first process reads; an invalid option; a solve not
distributed yet) must end every process with one message and the serial
exit code, and write nothing.
"""
import os
import sys

import h5py
import numpy as np
from mpi_harness import Harness, kExitInputError as harness_exit_input_error, kFieldTolerance, kProcessCounts, kRunAttributes, kVonMisesPosition

# The residual at convergence is rounding itself (1e-19 here): compared as
# the relative quantity it is, not relative to itself.
kAbsoluteAttributes = {"residual"}

harness = Harness(sys.argv)
mpi_program, serial_program, mpiexec, source_dir, work_dir = harness.arguments
fail = harness.fail


def attributes(node):
    return {name: node.attrs[name] for name in node.attrs}


def compare_attributes(where, got, want, skip=kRunAttributes):
    harness.compare_attributes(where, got, want, skip, kFieldTolerance, kAbsoluteAttributes)


def compare_files(where, got_path, want_path):
    with h5py.File(got_path, "r") as got, h5py.File(want_path, "r") as want:
        compare_attributes(where + " /", attributes(got), attributes(want), kRunAttributes | kVonMisesPosition)
        harness.check_von_mises_position(where, got, want)
        names = harness.same_objects(where, got, want)
        if names is None:
            return
        worst = 0.0
        for name in names:
            if not isinstance(want[name], h5py.Dataset):
                compare_attributes(f"{where} /{name}", attributes(got[name]), attributes(want[name]))
                continue
            a, b = got[name], want[name]
            compare_attributes(f"{where} /{name}", attributes(a), attributes(b))
            if a.shape != b.shape or a.dtype != b.dtype:
                fail(f"{where}: /{name} is {a.shape} {a.dtype}, serial {b.shape} {b.dtype}")
                continue
            x, y = a[()], b[()]
            if np.issubdtype(y.dtype, np.floating):
                scale = max(float(np.max(np.abs(y))), 1e-300)
                error = np.abs(x - y) / scale
                where_worst = np.unravel_index(int(np.argmax(error)), error.shape)
                worst = max(worst, float(np.max(error)))
                if float(np.max(error)) > kFieldTolerance:
                    fail(f"{where}: /{name} differs by {float(np.max(error)):.2e} of its largest value at "
                         f"{where_worst} (allowed {kFieldTolerance:.0e})")
            elif not np.array_equal(x, y):
                fail(f"{where}: /{name} differs in {int(np.count_nonzero(x != y))} cells")
        print(f"{where}: largest field difference {worst:.2e} of the field's largest value")


def solve_case(name, arguments, process_counts=kProcessCounts):
    serial_output = harness.serial_output(name, "solve", arguments)
    if serial_output is None:
        return
    for where, output in harness.distributed_outputs(name, "solve", arguments, process_counts):
        compare_files(where, output, serial_output)


failure_case = harness.refusal_case


common = ["--E-star", "1e11", "--threads", "1", "--fft-planning", "estimate", "--quiet"]
# Hertz: a sphere on a periodic 64 x 50 grid (50 rows: 17, 17 and 16 on 3
# processes), load controlled, both forms of Polonsky-Keer.
hertz = ["--geometry", "sphere", "--radius", "0.01", "--grid", "64x50", "--size", "1e-3x0.78125e-3",
         "--boundary", "periodic", "--force", "5"] + common
solve_case("hertz-pk-fourier", hertz + ["--solver", "pk-fourier", "--tol", "1e-12"])
solve_case("hertz-pk", hertz + ["--solver", "pk", "--tol", "1e-12"])
# Rough: the self-affine 128 x 128 example surface, periodic, under
# displacement and load control.
rough = ["--height-map", os.path.join(source_dir, "examples", "self_affine_128.h5"), "--boundary", "periodic",
         "--solver", "pk-fourier", "--tol", "1e-12"] + common
solve_case("rough-force", rough + ["--mean-pressure", "2e8"])
solve_case("rough-approach", rough + ["--approach", "1e-6"])
# Free (non-periodic) grids: the padded convolution with Love's coefficients.
# Hertz on a 64 x 51 grid (odd: 17 rows on each of 3 processes, the padded
# spectrum's 65 columns 22, 22 and 21), both solvers, load and displacement
# controlled.
free_hertz = ["--geometry", "sphere", "--radius", "0.01", "--grid", "64x51", "--size", "1e-3x0.796875e-3",
              "--boundary", "free", "--tol", "1e-12"] + common
solve_case("free-hertz-pk-fourier-force", free_hertz + ["--solver", "pk-fourier", "--force", "5"])
solve_case("free-hertz-pk-fourier-approach", free_hertz + ["--solver", "pk-fourier", "--approach", "4e-7"])
solve_case("free-hertz-pk-force", free_hertz + ["--solver", "pk", "--force", "5"])
solve_case("free-hertz-pk-approach", free_hertz + ["--solver", "pk", "--approach", "4e-7"])
# The rough example surface as a free one (many contact spots), 128 x 128.
free_rough = ["--height-map", os.path.join(source_dir, "examples", "self_affine_128.h5"), "--boundary", "free",
              "--tol", "1e-12"] + common
solve_case("free-rough-pk-fourier-force", free_rough + ["--solver", "pk-fourier", "--mean-pressure", "2e8"])
solve_case("free-rough-pk-fourier-approach", free_rough + ["--solver", "pk-fourier", "--approach", "1e-6"])
solve_case("free-rough-pk-force", free_rough + ["--solver", "pk", "--mean-pressure", "2e8"])
solve_case("free-rough-pk-approach", free_rough + ["--solver", "pk", "--approach", "1e-6"])
# Subsurface stresses (--stress-depths): every process computes and writes
# its rows of the /stress group, the largest von Mises stress and its
# position reduced over the processes; a homogeneous body on periodic and
# free grids, a coated one on a periodic grid (the free coated solve is not
# distributed), depths in the layer and below it.
stresses = ["--stress-depths", "1e-5,4e-5,1.2e-4"]
solve_case("hertz-stresses", hertz + ["--solver", "pk-fourier", "--tol", "1e-12", "--stress-nu", "0.3"] + stresses)
solve_case("free-hertz-stresses", free_hertz + ["--solver", "pk-fourier", "--force", "5", "--stress-nu", "0.3"] +
           stresses)
solve_case("free-rough-stresses", free_rough + ["--solver", "pk-fourier", "--mean-pressure", "2e8", "--stress-nu",
                                                "0.3"] + stresses)
solve_case("hertz-coated-stresses", hertz[:-len(common)] + common[2:] + [
    "--solver", "pk-fourier", "--tol", "1e-12", "--layer-thickness", "2e-5", "--layer-E", "3e11", "--layer-nu",
    "0.25", "--substrate-E", "7e10", "--substrate-nu", "0.33"] + stresses)

# On one process the MPI program solves what is not distributed yet as the
# serial program does: the default solver on one process equals the serial one.
solve_case("hertz-one-process-multilevel", hertz + ["--solver", "pk-multilevel", "--tol", "1e-12"], (1,))

# A 1D grid (one row, not split into slabs) on several processes: the first
# process solves it as the serial program does (subsurface stresses and a
# coated free half-space too), the others waiting.
line = ["--geometry", "cylinder", "--radius", "0.01", "--grid", "64", "--size", "1e-3", "--force", "1e3",
        "--solver", "pk-fourier"] + common
solve_case("line-periodic", line + ["--boundary", "periodic"], (2, 3))
solve_case("line-free-stresses", line + ["--boundary", "free", "--stress-depths", "1e-5,3e-5", "--stress-nu", "0.3"],
           (2, 3))
solve_case("line-free-coated", line[:-len(common)] + common[2:] + [
    "--boundary", "free", "--layer-thickness", "2e-5", "--layer-E", "3e11", "--layer-nu", "0.25",
    "--substrate-E", "7e10", "--substrate-nu", "0.33"], (2, 3))
# The dense solvers too, on a 1D grid (on a 2D one they are refused below).
solve_case("line-free-lemke", line[:10] + ["--boundary", "free", "--solver", "lemke", "--E-star", "1e11", "--quiet"],
           (2, 3))

# The paper command (its four small line contacts): the first process runs
# it as the serial program does, the others waiting; every column of its
# table equals the serial one within kFieldTolerance of the column's largest
# value.
paper = ["paper", "--test", "4", "--no-figures", "--quiet", "--output-dir"]
serial_paper = os.path.join(work_dir, "paper-serial")
if harness.run([serial_program] + paper + [serial_paper]).returncode != 0:
    fail("paper: the serial program failed")
for processes in (2, 3):
    paper_dir = os.path.join(work_dir, f"paper-np{processes}")
    result = harness.run_mpi(processes, paper + [paper_dir])
    where = f"paper, {processes} processes"
    written = os.path.join(paper_dir, "test4.csv")
    if result.returncode != 0 or not os.path.isfile(written):
        fail(f"{where}: exit {result.returncode}: {result.stderr.strip()}")
        continue
    want = np.genfromtxt(os.path.join(serial_paper, "test4.csv"), delimiter=",", names=True)
    got = np.genfromtxt(written, delimiter=",", names=True)
    if got.dtype.names != want.dtype.names or got.shape != want.shape:
        fail(f"{where}: columns {got.dtype.names} {got.shape}, serial {want.dtype.names} {want.shape}")
        continue
    for column in want.dtype.names:
        scale = max(float(np.max(np.abs(want[column]))), 1e-300)
        if float(np.max(np.abs(got[column] - want[column]))) > kFieldTolerance * scale:
            fail(f"{where}: column {column} differs from the serial table")
    print(f"{where}: test4.csv equals the serial program's")


# The stress command on several processes: the first process reads the
# result, each computes and writes its rows of the stress file, which must be
# the serial command's. Results of the cases above (periodic, free, rough,
# coated, a 1D one run by the first process alone), a coated free one and
# friction results (pressure and shear) made by the serial program.
def stress_command_case(name, result, arguments, process_counts=kProcessCounts):
    serial_output = os.path.join(work_dir, f"{name}-stress-serial.h5")
    serial = harness.run([serial_program, "stress", result] + arguments + ["--quiet", "--output", serial_output])
    if serial.returncode != 0:
        fail(f"stress {name}: the serial program failed ({serial.returncode}): {serial.stderr.strip()}")
        return
    for processes in process_counts:
        output = os.path.join(work_dir, f"{name}-stress-np{processes}.h5")
        if os.path.exists(output):
            os.remove(output)
        distributed = harness.run_mpi(processes, ["stress", result] + arguments + ["--quiet", "--output", output])
        where = f"stress {name}, {processes} processes"
        if distributed.returncode != 0:
            fail(f"{where}: exit {distributed.returncode}: {distributed.stderr.strip()}")
            continue
        compare_files(where, output, serial_output)
        if harness.temporaries():
            fail(f"{where}: temporaries left behind: {harness.temporaries()}")


def serial_result(name, arguments):
    output = os.path.join(work_dir, f"{name}-serial.h5")
    result = harness.run([serial_program, "solve"] + arguments + ["--output", output])
    if result.returncode != 0:
        fail(f"{name}: the serial program failed ({result.returncode}): {result.stderr.strip()}")
    return output


depths = ["--depths", "1e-5,4e-5,1.2e-4"]
stress_command_case("hertz", os.path.join(work_dir, "hertz-pk-fourier-serial.h5"), depths + ["--nu", "0.3"])
stress_command_case("free-rough", os.path.join(work_dir, "free-rough-pk-fourier-force-serial.h5"),
                    ["--depth-range", "5e-6:1e-4:4", "--nu", "0.25"])
stress_command_case("hertz-coated", os.path.join(work_dir, "hertz-coated-stresses-serial.h5"), depths)
coating = ["--layer-thickness", "2e-5", "--layer-E", "3e11", "--layer-nu", "0.25", "--substrate-E", "7e10",
           "--substrate-nu", "0.33"]
stress_command_case("free-hertz-coated", serial_result("free-hertz-coated", free_hertz[:-len(common)] + common[2:] + [
    "--solver", "pk-fourier", "--force", "5"] + coating), depths)
steel = ["--E1", "2.1e11", "--nu1", "0.3", "--E2", "2.1e11", "--nu2", "0.3"]
for boundary in ("periodic", "free"):
    friction = ["--geometry", "sphere", "--radius", "0.01", "--grid", "48x38", "--size", "4e-4x3.2e-4",
                "--boundary", boundary, "--force", "5", "--friction", "0.3", "--tangential-force", "0.6,0.2",
                "--threads", "1", "--fft-planning", "estimate", "--quiet", "--solver", "pk-fourier"] + steel
    stress_command_case(f"{boundary}-friction", serial_result(f"{boundary}-friction", friction),
                        ["--depths", "1e-5,3e-5,9e-5", "--nu", "0.3"])
stress_command_case("line", os.path.join(work_dir, "line-free-stresses-serial.h5"),
                    ["--depths", "1e-5,3e-5", "--nu", "0.3"], (2, 3))
# Options checked against the result (read by the first process) fail on
# every process alike: one message, the serial exit code, no file.
for processes in (2, 3):
    refused = os.path.join(work_dir, "stress-refused.h5")
    result = harness.run_mpi(processes, ["stress", os.path.join(work_dir, "hertz-pk-fourier-serial.h5"), "--depths",
                                         "1e-5", "--output", refused])
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    where = f"stress without --nu, {processes} processes"
    if result.returncode != harness_exit_input_error or len(errors) != 1 or "Poisson's ratio" not in errors[0]:
        fail(f"{where}: exit {result.returncode}, errors {errors}")
    if os.path.exists(refused):
        fail(f"{where}: {refused} was written")

missing = os.path.join(work_dir, "failure.h5")
for processes in (2, 3):
    failure_case("bad file", processes, ["--height-map", os.path.join(work_dir, "no-such-map.h5"), "--boundary",
                                         "periodic", "--mean-pressure", "1e6", "--solver", "pk-fourier"] + common,
                 "no-such-map.h5", missing)
    failure_case("invalid option", processes, hertz + ["--solver", "pk-fourier", "--tol", "2"], "tol", missing)
    failure_case("dense solver on slabs", processes, hertz + ["--solver", "lemke"],
                 "type = lemke is not available on slabs of a 2D grid: the dense solvers assemble the whole "
                 "influence matrix", missing)
    failure_case("mixed precision not distributed yet", processes,
                 hertz + ["--solver", "pk-fourier", "--precision", "mixed"],
                 "precision = mixed is not available with more than one process yet", missing)

harness.finish()
print("all distributed solves match the serial program")
