#!/usr/bin/env python3
"""The MPI program's parallel input and output against the serial program
(HALFSPACE_MPI builds; ctest runs it).

usage: parallel_io_test.py MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR

- HDF5 height maps that every process reads in rows (integer, float32 and
  float64 storage, a dataset in a group, a validity mask, spacing from the
  file, every detrending) on 2 and 3 processes (3: uneven slabs): the result
  file's /height, which is the map as read and prepared, and its preparation
  record equal the serial program's; height maps read by the first process
  alone (npy, invalid points filled) likewise.
- Built-in surfaces made per slab: /height bit for bit the serial one.
- Result files written collectively on 1, 2 and 3 processes: the serial
  file's datasets, shapes, types, storage (chunks, filters) and attributes;
  fields within kFieldTolerance of their largest value; contact statistics
  equal (clusters exactly, and the count checked against a labelling of
  the file's contact map done here, across the periodic edges); the XDMF
  sidecar the first process writes equal to the serial one.
- Failures (a missing dataset, a file that is not HDF5, a non-finite height
  in a later slab, an output that cannot be written, too little memory):
  one error line, the serial program's message and exit code, no output and
  no temporary left.
"""
import os
import sys
from collections import deque

import h5py
import numpy as np
from mpi_harness import Harness, kFieldTolerance, kProcessCounts, kRunAttributes

# The residual at convergence is rounding itself: compared absolutely.
kAbsoluteAttributes = {"residual"}

harness = Harness(sys.argv)
mpi_program, serial_program, mpiexec, source_dir, work_dir = harness.arguments
fail = harness.fail


def leftovers():
    return [f for f in os.listdir(work_dir) if ".tmp-" in f]


def compare_attributes(where, got, want):
    harness.compare_attributes(where, got, want, kRunAttributes, kFieldTolerance, kAbsoluteAttributes)


def storage(dataset):
    return dataset.chunks, dataset.compression, dataset.compression_opts, dataset.shuffle


def compare_files(where, got_path, want_path, exact=()):
    with h5py.File(got_path, "r") as got, h5py.File(want_path, "r") as want:
        compare_attributes(where + " /", dict(got.attrs), dict(want.attrs))
        names = harness.same_objects(where, got, want)
        if names is None:
            return
        worst = 0.0
        for name in names:
            a, b = got[name], want[name]
            compare_attributes(f"{where} /{name}", dict(a.attrs), dict(b.attrs))
            if not isinstance(b, h5py.Dataset):
                continue
            if a.shape != b.shape or a.dtype != b.dtype:
                fail(f"{where}: /{name} is {a.shape} {a.dtype}, serial {b.shape} {b.dtype}")
                continue
            if storage(a) != storage(b):
                fail(f"{where}: /{name} is stored as {storage(a)}, serial {storage(b)}")
            x, y = a[()], b[()]
            if name in exact or not np.issubdtype(y.dtype, np.floating):
                if not np.array_equal(x, y):
                    fail(f"{where}: /{name} differs in {int(np.count_nonzero(x != y))} cells (must be equal)")
                continue
            scale = max(float(np.max(np.abs(y))), 1e-300)
            error = float(np.max(np.abs(x - y))) / scale
            worst = max(worst, error)
            if error > kFieldTolerance:
                fail(f"{where}: /{name} differs by {error:.2e} of its largest value (allowed {kFieldTolerance:.0e})")
        print(f"{where}: same layout and attributes; largest field difference {worst:.2e}")
    # The XDMF sidecar, written by the first process, is the serial one's but
    # for the file name it points to.
    sidecars = [os.path.splitext(path)[0] + ".xdmf" for path in (got_path, want_path)]
    if not all(os.path.isfile(path) for path in sidecars):
        fail(f"{where}: no XDMF sidecar beside {got_path} or {want_path}")
        return
    got_text, want_text = (open(path).read() for path in sidecars)
    if got_text.replace(os.path.basename(got_path) + ":", os.path.basename(want_path) + ":") != want_text:
        fail(f"{where}: the XDMF sidecar {sidecars[0]} differs from the serial {sidecars[1]}")


def periodic_clusters(contact):
    """Connected components of the contact cells, 4-neighbours, wrapping at
    the edges: an independent count of the file's clusters."""
    ny, nx = contact.shape
    seen = np.zeros_like(contact, dtype=bool)
    sizes = []
    for j0, i0 in zip(*np.nonzero(contact)):
        if seen[j0, i0]:
            continue
        seen[j0, i0] = True
        queue, size = deque([(j0, i0)]), 0
        while queue:
            j, i = queue.popleft()
            size += 1
            for dj, di in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                q, r = (j + dj) % ny, (i + di) % nx
                if contact[q, r] and not seen[q, r]:
                    seen[q, r] = True
                    queue.append((q, r))
        sizes.append(size)
    return sizes


def solve_case(name, arguments, process_counts=kProcessCounts, exact=(), check_clusters=False, exit_code=0):
    serial_output = harness.serial_output(name, "solve", arguments, exit_code)
    if serial_output is None:
        return
    if check_clusters:
        with h5py.File(serial_output, "r") as f:
            counted = len(periodic_clusters(f["contact"][()] != 0))
            if int(f.attrs["clusters"]) != counted or counted < 2:
                fail(f"{name}: the serial file records {int(f.attrs['clusters'])} clusters, counted {counted}")
            else:
                print(f"{name}: {counted} contact clusters")
    for where, output in harness.distributed_outputs(name, "solve", arguments, process_counts, exit_code):
        compare_files(where, output, serial_output, exact)


def failure_case(name, processes, arguments, message, output, same_message=True):
    """The MPI program must fail as the serial one does: same exit code, the
    same one error line (unless it names a process id), no output, no
    temporary."""
    serial = harness.run([serial_program, "solve"] + arguments + ["--output", output])
    result = harness.run_mpi(processes, ["solve"] + arguments + ["--output", output])
    where = f"{name}, {processes} processes"
    serial_errors = [line for line in serial.stderr.splitlines() if line.startswith("error:")]
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    if serial.returncode == 0 or result.returncode != serial.returncode:
        fail(f"{where}: exit {result.returncode}, serial {serial.returncode}; stderr: {result.stderr.strip()}")
    if len(errors) != 1 or message not in errors[0]:
        fail(f"{where}: expected one error line containing {message!r}, got {errors}")
    elif same_message and errors != serial_errors:
        fail(f"{where}: error {errors}, serial {serial_errors}")
    if os.path.isfile(output):
        fail(f"{where}: the output {output} was written")
        os.remove(output)  # so that the next case is judged on its own
    if leftovers():
        fail(f"{where}: temporaries left behind: {leftovers()}")
    print(f"{where}: {errors[0] if errors else result.stderr.strip()}")


def write_map(name, heights, dataset="height", dx=None, dy=None, valid=None):
    path = os.path.join(work_dir, name)
    with h5py.File(path, "w") as f:
        f.create_dataset(dataset, data=heights)
        if valid is not None:
            f.create_dataset(os.path.dirname("/" + dataset) + "/valid", data=valid)
        if dx is not None:
            f.attrs["dx"] = dx
        if dy is not None:
            f.attrs["dy"] = dy
    return path


common = ["--E-star", "1e11", "--threads", "1", "--fft-planning", "estimate", "--quiet", "--boundary", "periodic",
          "--solver", "pk-fourier"]

# A rough map on 96 x 50 points (3 processes: 17, 17, 16 rows): the example
# surface's corner plus a tilt and a curvature for the detrending to remove.
with h5py.File(os.path.join(source_dir, "examples", "self_affine_128.h5"), "r") as f:
    example = f["height"][()]
    spacing = float(f.attrs["dx"])
rows, cols = 50, 96
y, x = np.mgrid[0:rows, 0:cols].astype(float)
rough = example[:rows, :cols] + 2e-8 * (x / cols) + 3e-8 * (y / rows) ** 2
amplitude = float(np.max(np.abs(rough)))
maps = {
    "float64": write_map("rough-f8.h5", rough, dx=spacing, dy=spacing),
    "float32": write_map("rough-f4.h5", rough.astype(np.float32), dx=spacing, dy=spacing),
    "int16-in-group": write_map("rough-i2.h5", np.round(rough / amplitude * 3e4).astype(np.int16),
                                dataset="surface/z", valid=np.ones((rows, cols), np.uint8)),
}
load = ["--mean-pressure", "5e7", "--tol", "1e-10"]
solve_case("read float64", ["--height-map", maps["float64"]] + load + common, (2, 3), exact=("height",))
solve_case("read float32", ["--height-map", maps["float32"]] + load + common, (2, 3), exact=("height",))
# Integer heights: a map of 1 m units; spacing from the options.
solve_case("read int16 in a group with a mask",
           ["--height-map", maps["int16-in-group"], "--dataset", "/surface/z", "--dx", "1e-3", "--dy", "1e-3",
            "--mean-pressure", "1e6", "--tol", "1e-10", "--E-star", "1e5"] + common[2:],
           (2, 3), exact=("height",))
for detrend in ("mean", "plane", "curvature"):
    solve_case(f"read with detrend {detrend}", ["--height-map", maps["float64"], "--detrend", detrend] + load + common,
               (2, 3))
# Read by the first process alone and handed out: npy, and invalid points filled.
np.save(os.path.join(work_dir, "rough.npy"), rough)
solve_case("read npy on the first process", ["--height-map", os.path.join(work_dir, "rough.npy"), "--dx",
                                             str(spacing), "--dy", str(spacing)] + load + common, (2, 3),
           exact=("height",))
holed = rough.copy()
holed[30, 40] = np.nan
solve_case("read with invalid points filled",
           ["--height-map", write_map("holed.h5", holed, dx=spacing, dy=spacing), "--invalid", "fill"] + load + common,
           (2, 3))

# The written file: a field above 65536 values is chunked and compressed, so
# the storage is compared too (300 x 250: 84, 83, 83 rows on 3 processes).
sphere = ["--geometry", "sphere", "--radius", "0.01", "--grid", "300x250", "--size", "1e-3x0.8333333e-3",
          "--force", "2"] + common
hertz = sphere + ["--tol", "1e-11"]
solve_case("write hertz 300x250", hertz, exact=("height",))
# Contact statistics with many clusters, which cross slab boundaries and the
# periodic edges.
solve_case("write rough clusters", ["--height-map", maps["float64"], "--mean-pressure", "2e8", "--tol", "1e-11"] +
           common, check_clusters=True, exact=("height",))
for shape, parameters in (("wavy", ["--wavelength", "2.5e-4", "--amplitude", "1e-7"]),
                          ("cylinder", ["--radius", "0.02"])):
    solve_case(f"built-in {shape}", ["--geometry", shape] + parameters +
               ["--grid", "64x50", "--size", "1e-3x0.78125e-3", "--force", "1", "--tol", "1e-11"] + common,
               (2, 3), exact=("height",))

# Two rows on three processes: one holds none, and still takes part in the
# collective reading, statistics and writing.
solve_case("built-in wavy on 2 rows", ["--geometry", "wavy", "--wavelength", "2.5e-4", "--amplitude", "1e-7",
                                       "--grid", "40x2", "--size", "1e-3x5e-5", "--force", "0.05", "--tol", "1e-11"] +
           common, (3,), exact=("height",))
two_rows = write_map("two-rows.h5", rough[:2, :40], dx=spacing, dy=spacing)
solve_case("read 2 rows", ["--height-map", two_rows, "--detrend", "plane", "--mean-pressure", "5e7", "--tol",
                           "1e-11"] + common, (3,))

# Not converged (exit 2): the file is still written, the serial one.
solve_case("not converged", sphere + ["--tol", "1e-11", "--max-iter", "3"], (2, 3), exact=("height",), exit_code=2)

output = os.path.join(work_dir, "failure.h5")
not_hdf5 = os.path.join(work_dir, "not-hdf5.h5")
with open(not_hdf5, "w") as f:
    f.write("ny nx\n1 2\n")
late_nan = rough.copy()
late_nan[45, 7] = np.inf  # in the last slab on 2 and 3 processes
late_nan[47, 90] = np.nan
late_nan_map = write_map("late-nan.h5", late_nan, dx=spacing, dy=spacing)
for processes in (2, 3):
    failure_case("missing dataset", processes, ["--height-map", maps["float64"], "--dataset", "/nope"] + load + common,
                 "the dataset does not exist", output)
    failure_case("not an HDF5 file", processes, ["--height-map", not_hdf5] + load + common,
                 "not an HDF5 file", output)
    failure_case("non-finite heights in a later slab", processes, ["--height-map", late_nan_map] + load + common,
                 "2 of 4800 heights are invalid", output)
    failure_case("output is a directory", processes, hertz, "it is a directory", work_dir + "/")
    failure_case("output directory missing", processes, hertz, "does not exist",
                 os.path.join(work_dir, "no-such-directory", "out.h5"))
    failure_case("too little memory", processes, ["--height-map", maps["float64"], "--max-memory", "1M"] + load +
                 common, "per process of", output, same_message=False)
    # A name whose temporary (name.tmp-PID) is too long for the file system:
    # the writing itself fails, after the solve.
    long_name = os.path.join(work_dir, "r" * 248 + ".h5")
    failure_case("temporary cannot be created", processes, hertz, "could not create temporary file", long_name,
                 same_message=False)

# A file-size limit below the result's size (32 KiB: `ulimit -f` counts
# 512-byte blocks in sh): met by the reservation on the first process before
# any field is written, so every process ends with the one message, not one
# process alone inside a collective write. Open MPI's shared-memory transport
# maps files larger than the limit, so the processes talk over TCP here.
for processes in (2, 3):
    limited = os.path.join(work_dir, "limited.h5")
    command = " ".join([mpi_program, "solve"] + hertz + ["--output", limited])
    result = harness.run([mpiexec, "--oversubscribe", "--mca", "btl", "self,tcp", "-np", str(processes), "sh", "-c",
                          "ulimit -f 64; exec " + command])
    where = f"file-size limit, {processes} processes"
    errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
    if result.returncode != 1:
        fail(f"{where}: exit {result.returncode}, expected 1; stderr: {result.stderr.strip()}")
    if len(errors) != 1 or "could not reserve" not in errors[0] or "File too large" not in errors[0]:
        fail(f"{where}: expected one error line about the reservation, got {errors}")
    if os.path.exists(limited) or leftovers():
        fail(f"{where}: output or temporaries left behind: {leftovers()}")
    print(f"{where}: {errors[0] if errors else result.stderr.strip()}")

harness.finish()
print("parallel reading and writing match the serial program")
