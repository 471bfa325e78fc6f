#!/usr/bin/env python3
"""Friction on several MPI processes against the serial program.

usage: distributed_friction_test.py MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR

`mpiexec -np 1, 2 and 3 MPI_PROGRAM solve --friction ...` (3 gives uneven
slabs) on a sphere with a ripple, periodic and free grids (and a cylinder
on a 1D grid, which the first process solves alone): a single step
under a tangential force, a fretting history under force and one under
displacement, gross sliding, and elastically dissimilar bodies (the coupled
normal-tangential alternation), must write the serial program's files: the
same datasets (the friction fields /shear_x, /shear_y, /stick, /slip_x,
/slip_y, /tangential_displacement_x, _y, a history's /steps/NNN groups and
/history table), shapes, types and attributes, floating-point fields within
kTolerance of their largest value (a vector field's components, x and y,
of the larger of the two: a y component of a load along x is small, and
its error is the vector's), the stick and contact maps identical,
floating-point attributes within kTolerance relative (a force's or an
approach's components relative to the largest in the history: the force
of an unloaded step is rounding), a history's CSV the same columns within
kTolerance. What stays refused on several processes names the reason.

The tangential tolerance is 1e-13: the iterations follow the serial path
(the same counts), but at 1e-10 to 1e-12 the step after the load reverses
on the free grid stops at a state within its tolerance that hinges on
rounding (whether a cell is at mu p to 1e-12), 5e-12 to 1.5e-10 of the
shear's largest value from the serial one (measured on 3 processes); at
1e-13 both reach the unique solution, 3e-14 apart.
"""
import csv
import math
import os
import subprocess
import sys

import h5py
import numpy as np
from mpi_harness import Harness, kVonMisesPosition

# FFTW-MPI's transforms and the sums over the processes round differently
# from the serial ones: equal to rounding, not bitwise.
kTolerance = 1e-12
# Attributes that record the run, not the result (the CSV's digest: its
# numbers are equal to rounding, compared below).
kRunAttributes = {"solve_seconds", "seconds", "command_line", "halfspace_version", "history_csv_md5"}
# Residuals near convergence are rounding themselves: compared absolutely.
kAbsolute = {"residual", "residual_history", "tangential_residual", "coupling_residual"}
kProcessCounts = (1, 2, 3)

harness = Harness(sys.argv)
mpi_program, serial_program, mpiexec, source_dir, work_dir = harness.arguments
fail = harness.fail


def vector_scales(want):
    """The largest force and approach of a file (a history's steps, or the
    single step's), the scale of their components."""
    if "history" in want:
        table = want["history"]
        force = float(np.max(np.hypot(table["Q_x"][()], table["Q_y"][()])))
        approach = float(np.max(np.hypot(table["delta_x"][()], table["delta_y"][()])))
    else:
        a = want.attrs
        force = math.hypot(a.get("tangential_force_x", 0.0), a.get("tangential_force_y", 0.0))
        approach = math.hypot(a.get("tangential_approach_x", 0.0), a.get("tangential_approach_y", 0.0))
    return {"tangential_force": force, "tangential_approach": approach, "Q": force, "delta": approach}


def vector_scale(name, scales):
    """The scale of a force's or an approach's component: the largest of
    its vector (None for other attributes)."""
    if name[-2:] in ("_x", "_y") and name[:-2] in scales:
        return max(scales[name[:-2]], 1e-300)
    return None


def field_scale(name, group, values):
    """A field's largest magnitude, or its vector's (x and y)."""
    if name[-2:] in ("_x", "_y") and name[:-2] + "_x" in group and name[:-2] + "_y" in group:
        return max(float(np.max(np.abs(group[name[:-2] + "_x"][()]))),
                   float(np.max(np.abs(group[name[:-2] + "_y"][()]))), 1e-300)
    return max(float(np.max(np.abs(values))), 1e-300) if values.size else 1.0


def compare_attributes(where, got, want, scales, skip=kRunAttributes):
    harness.compare_attributes(where, got, want, skip, kTolerance, kAbsolute,
                               lambda name: vector_scale(name, scales))


def compare_files(where, got_path, want_path, required):
    with h5py.File(got_path, "r") as got, h5py.File(want_path, "r") as want:
        scales = vector_scales(want)
        compare_attributes(where + " /", got.attrs, want.attrs, scales, kRunAttributes | kVonMisesPosition)
        harness.check_von_mises_position(where, got, want)
        names = harness.same_objects(where, got, want, required)
        if names is None:
            return
        worst = 0.0
        for name in names:
            compare_attributes(f"{where} /{name}", got[name].attrs, want[name].attrs, scales)
            if not isinstance(want[name], h5py.Dataset):
                continue
            base = name.split("/")[-1]
            worst = max(worst, harness.compare_dataset(
                where, name, got[name], want[name], kTolerance,
                lambda y: 1.0 if base in kAbsolute else field_scale(base, want[name].parent, y)))
        print(f"{where}: largest field difference {worst:.2e} of the field's largest value")


def compare_tables(where, got_path, want_path):
    with open(got_path) as got_file, open(want_path) as want_file:
        got, want = list(csv.reader(got_file)), list(csv.reader(want_file))
    if len(got) != len(want) or got[0] != want[0]:
        fail(f"{where}: the history table has {len(got)} lines {got[:1]}, serial {len(want)} {want[:1]}")
        return
    columns = np.array([[float(v) for v in row] for row in want[1:]])
    values = np.array([[float(v) for v in row] for row in got[1:]])
    scale = np.maximum(np.max(np.abs(columns), axis=0), 1e-300)
    for x, y in ((1, 2), (3, 4)):  # Q_x, Q_y and delta_x, delta_y: the vectors' largest
        scale[x] = scale[y] = max(scale[x], scale[y])
    error = float(np.max(np.abs(values - columns) / scale))
    if error > kTolerance:
        fail(f"{where}: the history table differs by {error:.2e} of a column's largest value")


def friction_case(name, arguments, required):
    serial_output = harness.serial_output(name, "solve", arguments)
    if serial_output is None:
        return
    for where, output in harness.distributed_outputs(name, "solve", arguments, kProcessCounts):
        compare_files(where, output, serial_output, required)
        if os.path.exists(serial_output[:-3] + ".csv"):
            compare_tables(where, output[:-3] + ".csv", serial_output[:-3] + ".csv")


steel = ["--E1", "2.1e11", "--nu1", "0.3", "--E2", "2.1e11", "--nu2", "0.3"]
dissimilar = ["--E1", "2.1e11", "--nu1", "0.3", "--E2", "7e10", "--nu2", "0.33"]
fields = ("shear_x", "shear_y", "stick", "slip_x", "slip_y", "tangential_displacement_x", "tangential_displacement_y")
for boundary in ("periodic", "free"):
    # 48 x 38 cells: rows not a multiple of 3 (uneven slabs); the contact
    # (radius about 80 um, the ripple making it irregular) crosses the slabs.
    sphere = ["--geometry", "sphere", "--radius", "0.01", "--grid", "48x38", "--size", "4e-4x3.2e-4",
              "--boundary", boundary, "--force", "5", "--friction", "0.3", "--threads", "1",
              "--fft-planning", "estimate", "--quiet", "--tol", "1e-12", "--tangential-tol", "1e-13",
              "--solver", "pk-fourier"]
    history = ("steps/000/shear_x", "steps/003/stick", "history/Q_x", "history/dissipated_energy")
    friction_case(f"{boundary}-single-step", sphere + steel + ["--tangential-force", "0.6,0.2"], fields)
    # Subsurface stresses under the step's pressure and shear, each process
    # its rows of /stress.
    friction_case(f"{boundary}-single-step-stresses",
                  sphere + steel + ["--tangential-force", "0.6,0.2", "--stress-depths", "1e-5,3e-5,9e-5"],
                  fields + ("stress/von_mises", "stress/sigma_xz"))
    friction_case(f"{boundary}-fretting-force", sphere + steel + ["--tangential-force", "0:1.2:3;0.4;-0.8;0"],
                  fields + history)
    friction_case(f"{boundary}-fretting-displacement",
                  sphere + steel + ["--tangential-displacement", "0:6e-8:3;2e-8,1e-8;-4e-8"], fields + history)
    friction_case(f"{boundary}-sliding", sphere + steel + ["--sliding", "1,0.5"], fields)
    # Coupled: each step's group holds its own pressure and contact.
    friction_case(f"{boundary}-dissimilar", sphere + dissimilar + ["--tangential-force", "0.4;0.9;0.2;-0.5",
                                                                  "--normal-load-steps", "2"],
                  fields + history + ("steps/001/pressure", "steps/003/contact"))
    friction_case(f"{boundary}-dissimilar-single", sphere + dissimilar + ["--tangential-force", "0.9"], fields)

# A 1D grid: solved by the first process as the serial program does.
friction_case("line-fretting", ["--geometry", "cylinder", "--radius", "0.01", "--grid", "128", "--size", "1e-3",
                                "--force", "1e3", "--friction", "0.3", "--tangential-force", "100;200;-100",
                                "--threads", "1", "--quiet", "--fft-planning", "estimate"] + steel, fields)

# --plot on several processes: the first process runs the plotting tool on
# the written file, once per figure, as the serial program does. A stand-in
# interpreter (HALFSPACE_PYTHON) records each run (and passes the package
# check); the records of the serial and the distributed runs must list the
# same figures, and a failing tool gives the serial exit code 3 with the
# file written.
kExitPlotFailed = 3


def plot_case(name, arguments, processes=2, tool_fails=False):
    records = {}
    for program in ("serial", "mpi"):
        record = os.path.join(work_dir, f"plot-{name}-{program}.txt")
        interpreter = os.path.join(work_dir, f"plot-{name}-{program}.sh")
        with open(interpreter, "w") as script:
            script.write('#!/bin/sh\nif [ "$1" = "-c" ]; then exit 0; fi\n'
                         f'echo "$2 $(basename "$3")" >> "{record}"\nexit {1 if tool_fails else 0}\n')
        os.chmod(interpreter, 0o755)
        if os.path.exists(record):
            os.remove(record)
        output = os.path.join(work_dir, f"plot-{name}.h5")
        environment = dict(harness.environment, HALFSPACE_PYTHON=interpreter, HALFSPACE_PLOT_TOOL=interpreter)
        command = ["solve"] + arguments + ["--plot", "--output", output]
        command = ([serial_program] + command if program == "serial" else
                   [mpiexec, "--oversubscribe", "-np", str(processes), mpi_program] + command)
        result = subprocess.run(command, env=environment, capture_output=True, text=True, timeout=300)
        expected = kExitPlotFailed if tool_fails else 0
        where = f"--plot {name}, {program}"
        if result.returncode != expected:
            fail(f"{where}: exit {result.returncode}, expected {expected}: {result.stderr.strip()}")
        if not os.path.exists(output):
            fail(f"{where}: no result written")
        records[program] = open(record).read().splitlines() if os.path.exists(record) else []
    if not records["serial"]:
        fail(f"--plot {name}: the serial program drew nothing: the case does not test what it should")
    if records["mpi"] != records["serial"]:
        fail(f"--plot {name}: {processes} processes drew {records['mpi']}, serial {records['serial']}")
    print(f"--plot {name}, {processes} processes: {records['mpi']}")


plain = ["--geometry", "sphere", "--radius", "0.01", "--grid", "32x26", "--size", "4e-4x3.2e-4", "--E-star", "1e11",
         "--solver", "pk-fourier", "--threads", "1", "--quiet"]
plot_case("single", plain + ["--force", "5"])
plot_case("sweep", plain + ["--force", "2:5:2"])
plot_case("friction-history", plain[:8] + steel + plain[10:] + ["--force", "5", "--friction", "0.3",
                                                                "--tangential-force", "0.6;0.2"], 3)
plot_case("failing-tool", plain + ["--force", "5"], tool_fails=True)

# What several processes do not run yet, refused with the reason.
base = ["--geometry", "sphere", "--radius", "0.01", "--force", "5", "--friction", "0.3",
        "--tangential-force", "0.6", "--threads", "1", "--quiet"] + steel
refused = os.path.join(work_dir, "refused.h5")
harness.refusal_case("friction with lemke", 2, base + ["--grid", "16x16", "--size", "4e-4x4e-4", "--solver", "lemke"],
                     "type = lemke is not available on slabs of a 2D grid", refused)

harness.finish()
print("all friction runs match the serial program")
