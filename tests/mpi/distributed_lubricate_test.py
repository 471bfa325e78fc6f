#!/usr/bin/env python3
"""`mpiexec halfspace lubricate` against the serial program (HALFSPACE_MPI
builds; ctest runs it).

usage: distributed_lubricate_test.py MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR

The steady rigid film of a 2D map on 1, 2 and 3 processes (3: uneven slabs)
must write the serial program's file: the same datasets, shapes, types and
attributes. Under separation control the solver's iterates are the serial
ones, so every field equals the serial one to the bit; the forces and flows
are sums over the processes, added in another order, so the attributes
(and under load control, the separation found from them, hence the fields)
equal the serial ones within kFieldTolerance. Cases: fixed edges with
entrainment along x and oblique, y-periodic with entrainment down and up,
x-periodic, load control, a prepared map (window and detrending), shear
limits; a profile (one row) on several processes is run by the first
process as the serial program runs it, elastic films included, and so is
the transient film of a map, whose solver does not run on slabs: their
files must be the serial program's to the bit. The EHL and mixed films of
a map run on slabs (their own GMRES iterates: each process preconditions
its own rows), so their files must equal the serial ones to the solver's
tolerance (kElasticTolerance), on free and periodic bodies, the EHL film
homogeneous and coated, with the first- and second-order Couette flux. A mixed
film's Stribeck sweep shares out its speeds, and its curve and last film
must equal the serial ones to the solver's tolerance. --plot, a map with
fewer rows than processes, and EHL and mixed films whose halo needs more
rows than a process holds must be refused by every process with one message and no
file.
"""
import os
import sys

import h5py
import numpy as np
from mpi_harness import Harness, kFieldTolerance, kProcessCounts, kRunAttributes

# The residual, the load error and the complementarity error are
# rounding-sized: compared in absolute terms.
kAbsoluteAttributes = {"relative_residual", "load_error", "complementarity_error"}
# A force's components are compared relative to its magnitude: a component
# that cancels (y on a film symmetric about its centre line) is rounding
# about 0, which its own size would not measure.
kForceVectors = {f"{force}_{axis}": force
                 for force in ("friction_force", "couette_friction_force", "fluid_friction_force",
                               "contact_friction_force")
                 for axis in "xy"}
# The fields of a film file.
kFields = ("pressure", "film", "fluid_fraction", "shear_x", "shear_y")

harness = Harness(sys.argv)
mpi_program, serial_program, mpiexec, source_dir, work_dir = harness.arguments
fail = harness.fail


def compare_files(where, got_path, want_path, bitwise, required=kFields, tolerance=kFieldTolerance,
                  skip=kRunAttributes):
    with h5py.File(got_path, "r") as got, h5py.File(want_path, "r") as want:
        def force_scale(name):
            if name not in kForceVectors:
                return None
            force = kForceVectors[name]
            return max(float(np.hypot(want.attrs[force + "_x"], want.attrs[force + "_y"])), 1e-300)

        harness.compare_attributes(where + " /", dict(got.attrs), dict(want.attrs), skip, tolerance,
                                   kAbsoluteAttributes, force_scale)
        names = harness.same_objects(where, got, want, required=required)
        if names is None:
            return
        worst = 0.0
        for name in names:
            harness.compare_attributes(f"{where} /{name}", dict(got[name].attrs), dict(want[name].attrs),
                                       kRunAttributes, tolerance)
            if isinstance(want[name], h5py.Group):  # a transient film's history and steps: their datasets follow
                continue
            worst = max(worst, harness.compare_dataset(where, name, got[name], want[name], tolerance))
            if bitwise and not np.array_equal(got[name][()], want[name][()]):
                fail(f"{where}: /{name} is not the serial field to the bit")
        print(f"{where}: largest field difference {worst:.2e} of the field's largest value"
              + (" (fields equal to the bit)" if bitwise and worst == 0.0 else ""))


def film_case(name, arguments, bitwise, process_counts=kProcessCounts, required=kFields, text_files=(),
              tolerance=kFieldTolerance, skip=kRunAttributes):
    """`text_files`: suffixes of files written beside the output (a
    transient film's history CSV) that must equal the serial ones; `skip`:
    root attributes compared by presence."""
    serial_output = harness.serial_output(name, "lubricate", arguments)
    if serial_output is None:
        return
    for where, output in harness.distributed_outputs(name, "lubricate", arguments, process_counts):
        compare_files(where, output, serial_output, bitwise, required, tolerance, skip)
        for suffix in text_files:
            got_text, want_text = (os.path.splitext(path)[0] + suffix for path in (output, serial_output))
            if not os.path.exists(got_text) or not os.path.exists(want_text):
                fail(f"{where}: {suffix} file missing ({got_text}, {want_text})")
            elif open(got_text).read() != open(want_text).read():
                fail(f"{where}: {got_text} differs from the serial {want_text}")


def generate(name, arguments):
    path = os.path.join(work_dir, name + ".h5")
    result = harness.run([serial_program, "generate"] + arguments + ["--quiet", "--output", path])
    if result.returncode != 0:
        fail(f"generate {name}: {result.stderr.strip()}")
    return path


# A ball on a 48 x 40 map (40 rows: 14, 14 and 12 on 3 processes), and a
# profile of a cylinder.
ball = generate("ball", ["--kind", "sphere", "--grid", "48x40", "--size", "1e-3x0.8e-3", "--radius", "0.01"])
cylinder = generate("cylinder", ["--kind", "cylinder", "--grid", "64", "--size", "1e-3", "--radius", "0.01"])
rough = os.path.join(source_dir, "examples", "self_affine_128.h5")
common = ["--viscosity", "0.1", "--quiet"]
on_ball = ["--height-map", ball] + common

# Separation control: the serial iterates on every process count.
film_case("fixed-along-x", on_ball + ["--entrainment-velocity", "1", "--sliding-velocity", "0.2",
                                      "--separation", "2e-6"], bitwise=True)
film_case("fixed-oblique-down", on_ball + ["--entrainment-velocity", "1,-0.4", "--sliding-velocity", "0.2,0.1",
                                           "--separation", "1e-6", "--side-pressure", "1e5"], bitwise=True)
film_case("periodic-y-down", on_ball + ["--entrainment-velocity", "1,-0.3", "--periodic-y", "--separation", "1e-6"],
          bitwise=True)
film_case("periodic-y-up", on_ball + ["--entrainment-velocity", "0.5,0.5", "--periodic-y", "--separation", "1e-6",
                                      "--inlet-pressure", "2e5"], bitwise=True)
film_case("periodic-x", on_ball + ["--entrainment-velocity", "1,0.2", "--periodic-x", "--separation", "1e-6",
                                   "--supply-fluid-fraction", "0.7"], bitwise=True)
film_case("shear-limits", on_ball + ["--entrainment-velocity", "1", "--sliding-velocity", "2", "--separation",
                                     "3e-7", "--eyring-stress", "5e6", "--limiting-shear-stress", "2e7"],
          bitwise=True)
# A prepared measured map: a window of the rough example, detrended.
film_case("rough-window", ["--height-map", rough, "--window", "8,4,64,45", "--detrend", "plane"] + common +
          ["--entrainment-velocity", "1,0.1", "--separation", "2e-6"], bitwise=True)
# Load control: the separation search on the forces' sums.
film_case("load-fixed", on_ball + ["--entrainment-velocity", "1,0.3", "--force", "5"], bitwise=False)
film_case("load-periodic-y", on_ball + ["--entrainment-velocity", "1,-0.3", "--periodic-y", "--force", "5"],
          bitwise=False)
# A profile: the first process runs it as one process does (the elastic
# film too).
profile = ["--height-map", cylinder] + common + ["--entrainment-velocity", "1"]
film_case("profile-rigid", profile + ["--force", "1e3"], bitwise=True, process_counts=(2, 3))
film_case("profile-elastic", profile + ["--force", "1e4", "--E-star", "1.1e11"], bitwise=True, process_counts=(2, 3))

# The EHL film of a map on slabs: solved to a relative mass residual of
# 1e-11, the fields agree far within kElasticTolerance (measured: at most
# 6.6e-12 of their largest values, on the second-order case); the relative
# residual and the load error are compared in absolute terms.
kElasticTolerance = 1e-7
base = on_ball + ["--entrainment-velocity", "1"]
elastic = ["--force", "5", "--E-star", "1e11", "--tolerance", "1e-11"]
kElasticFields = kFields + ("deformation",)
film_case("map-elastic", base + elastic, bitwise=False, required=kElasticFields, tolerance=kElasticTolerance)
film_case("map-elastic-oblique-second-order",
          on_ball + ["--entrainment-velocity", "1,0.4", "--couette-scheme", "second-order"] + elastic, bitwise=False,
          required=kElasticFields, tolerance=kElasticTolerance)
film_case("map-elastic-periodic", on_ball + ["--entrainment-velocity", "1,-0.3", "--periodic-y", "--boundary",
                                             "periodic"] + elastic,
          bitwise=False, required=kElasticFields, tolerance=kElasticTolerance)
film_case("map-elastic-coated", base + ["--force", "5", "--layer-thickness", "2e-5", "--layer-E", "3e11", "--layer-nu",
                                        "0.25", "--substrate-E", "2e11", "--substrate-nu", "0.3", "--tolerance",
                                        "1e-11"],
          bitwise=False, required=kElasticFields, tolerance=kElasticTolerance)

# The mixed film of a map on slabs, solved to a relative mass residual of
# 1e-11, at speeds where the contact carries 22 %, 9 % and 8 % of the load
# (measured: at most 3.5e-9 of the fields' largest values apart). Its
# Newton steps differ: the speed continuation's path depends on the GMRES
# iterates (the serial 83 steps against 73 and 116 on 2 and 3 processes).
kMixedSkip = kRunAttributes | {"iterations"}
kMixedFields = ("pressure", "fluid_pressure", "contact_pressure", "film", "fluid_fraction", "deformation")
mixed = ["--viscosity", "0.1", "--quiet", "--force", "5", "--E-star", "1e11", "--mixed", "--tolerance", "1e-11"]
film_case("map-mixed", ["--height-map", ball, "--entrainment-velocity", "0.003"] + mixed, bitwise=False,
          required=kMixedFields, tolerance=kElasticTolerance, skip=kMixedSkip)
film_case("map-mixed-oblique", ["--height-map", ball, "--entrainment-velocity", "0.003,0.0012"] + mixed,
          bitwise=False, required=kMixedFields, tolerance=kElasticTolerance, skip=kMixedSkip)
film_case("map-mixed-periodic", ["--height-map", ball, "--entrainment-velocity", "0.003,-0.001", "--periodic-y",
                                 "--boundary", "periodic"] + mixed,
          bitwise=False, required=kMixedFields, tolerance=kElasticTolerance, skip=kMixedSkip)


def trace_case(processes):
    """--trace on slabs: the first process writes each solve's line once
    (every process takes the same solves), numbered in order; the last is
    the film's, and the steps of the lines on the map's grid add up to the
    file's Newton steps."""
    where = f"map-mixed --trace, {processes} processes"
    trace = os.path.join(work_dir, f"trace-np{processes}.csv")
    output = os.path.join(work_dir, f"trace-np{processes}.h5")
    result = harness.run_mpi(processes, ["lubricate", "--height-map", ball, "--entrainment-velocity", "0.003"] + mixed +
                             ["--trace", trace, "--output", output])
    if result.returncode != 0:
        fail(f"{where}: exit {result.returncode}: {result.stderr.strip()}")
        return
    rows = np.atleast_1d(np.genfromtxt(trace, delimiter=",", names=True, dtype=None, encoding="utf-8"))
    with h5py.File(output, "r") as file:
        iterations = int(file.attrs["iterations"])
    fine = (rows["nx"] == 48) & (rows["ny"] == 40)
    if list(rows["solve"]) != list(range(1, len(rows) + 1)):
        fail(f"{where}: the solves are numbered {list(rows['solve'])}")
    if rows["status"][-1] != "converged" or not fine[-1]:
        fail(f"{where}: the last line is not the film's: {rows[-1]}")
    if int(np.sum(rows["newton_steps"][fine])) != iterations:
        fail(f"{where}: the fine lines' {int(np.sum(rows['newton_steps'][fine]))} Newton steps, the file's "
             f"{iterations}")
    print(f"{where}: {len(rows)} solves, {iterations} fine Newton steps")


for count in (2, 3):
    trace_case(count)

# The transient film of a map does not run on slabs: the first process
# solves it whole, as the serial program does.
film_case("map-transient", base + ["--separation", "1e-6", "--time-step", "1e-4", "--steps", "2",
                                   "--approach-velocity", "1e-3"], bitwise=True, process_counts=(2,),
          required=kFields + ("history/load", "steps/002/pressure"), text_files=(".csv",))

# A Stribeck sweep shares out its speeds: contiguous runs, the last on the
# first process, each run's first speed started as a single solve is (not
# from the previous speed), so the curve and the last film equal the
# serial ones to the accuracy the solver's tolerance gives, not to the bit.
# From full film to 22 % of the load on contact. The fields' error is here
# about 2,500 times the relative mass residual (a cold solve at 0.003 m/s
# that stopped at 8.5e-10 was 2.1e-6 of the peak pressure from the tight
# solution), so the sweep is solved to a mass residual of 1e-10 (the
# default 1e-8 could leave 2.5e-5).
kSweepTolerance = 1e-6


def sweep_case(name, arguments, process_counts):
    runs = {}
    for processes in (0,) + process_counts:
        where = f"{name}, {processes or 'serial'} processes"
        output = os.path.join(work_dir, f"{name}-{processes}.h5")
        curve = os.path.join(work_dir, f"{name}-{processes}.csv")
        command = ["lubricate"] + arguments + ["--stribeck", curve, "--output", output]
        result = harness.run([serial_program] + command) if processes == 0 else harness.run_mpi(processes, command)
        if result.returncode != 0:
            fail(f"{where}: exit {result.returncode}: {result.stderr.strip()}")
            continue
        runs[processes] = (where, output, np.genfromtxt(curve, delimiter=",", names=True, dtype=None,
                                                         encoding="utf-8"))
    if 0 not in runs:
        return
    _, serial_output, serial_curve = runs.pop(0)
    if "converged" not in set(serial_curve["status"]) or len(serial_curve) < 3:
        fail(f"{name}: the serial sweep did not run as the case needs: {serial_curve}")
    if not np.max(serial_curve["contact_load_fraction"]) > 0.1:
        fail(f"{name}: the serial sweep never reaches contact; the case tests less than it should")
    for where, output, curve in runs.values():
        if list(curve["status"]) != list(serial_curve["status"]):
            fail(f"{where}: statuses {list(curve['status'])}, serial {list(serial_curve['status'])}")
        worst = 0.0
        for column in serial_curve.dtype.names:
            if column in ("status", "newton_steps"):
                continue
            want, got = serial_curve[column], curve[column]
            scale = max(float(np.max(np.abs(want))), 1e-300)
            worst = max(worst, float(np.max(np.abs(got - want))) / scale)
        if worst > kSweepTolerance:
            fail(f"{where}: the Stribeck curve differs by {worst:.2e} of a column's largest value "
                 f"(allowed {kSweepTolerance:.0e})")
        with h5py.File(output, "r") as got, h5py.File(serial_output, "r") as want:
            for field in ("pressure", "fluid_pressure", "contact_pressure", "film", "fluid_fraction"):
                worst = max(worst, harness.compare_dataset(where, field, got[field], want[field], kSweepTolerance))
        print(f"{where}: largest difference {worst:.2e} of a column's or field's largest value")


sweep_case("mixed-sweep", base + ["--force", "5", "--E-star", "1e11", "--mixed", "--speeds", "0.03,0.01,0.003",
                                  "--tolerance", "1e-10"],
           process_counts=(1, 2, 3))

# Refused by every process alike, no file.
refused = os.path.join(work_dir, "refused.h5")
for name, arguments, message in [
        ("plot", ["--separation", "1e-6", "--plot"], "--plot is not available with more than one process"),
        # 4 rows on 3 processes: FFTW's slabs of 2 rows leave the third none.
        ("too-few-rows", ["--window", "0,0,48,4", "--separation", "1e-6"], "leaves a process without rows"),
        # 5 rows on 3 processes: 2, 2 and 1, and the second-order flux's halo is two rows.
        # 7 rows on 3 processes: 3, 3 and 1, and one row is no grid.
        ("one-row", ["--window", "0,0,48,7", "--separation", "1e-6"], "leaves a process with 1 row: each needs at least 2"),
        ("elastic-too-few-rows", ["--window", "0,0,48,5", "--force", "0.5", "--E-star", "1e11", "--couette-scheme",
                                  "second-order"], "leaves a process with 1 row: each needs at least 2"),
        ("mixed-too-few-rows", ["--window", "0,0,48,5", "--force", "0.5", "--E-star", "1e11", "--mixed",
                                "--couette-scheme", "second-order"], "leaves a process with 1 row: each needs at least 2"),
        # Each process would trace its own speeds.
        ("trace-shared-sweep", ["--force", "5", "--E-star", "1e11", "--mixed", "--speeds", "0.03,0.01", "--stribeck",
                                os.path.join(work_dir, "refused.csv"), "--trace", os.path.join(work_dir, "t.csv")],
         "with a Stribeck sweep on several processes")]:
    harness.refusal_case(f"refused {name}", 2 if name == "plot" else 3, base + arguments, message, refused,
                         command="lubricate")
if os.path.exists(os.path.join(work_dir, "t.csv")):
    fail("refused trace-shared-sweep: the trace was written")

harness.finish()
