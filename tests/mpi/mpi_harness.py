"""What every MPI test script shares: its arguments, the environment the
programs run in (one OpenMP thread, Open MPI allowed to run as root and to
oversubscribe the cores, no FFTW wisdom file, so that plans and results do
not depend on an earlier run), running the serial and the MPI program,
comparing the attributes and the objects of their files, and the list of
failures the script reports at its end (finish).

usage in a script: SCRIPT MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

import numpy as np

kExitInputError = 1  # the program's exit code for bad input
# The distributed reductions add the processes' partial sums in another order
# than the serial fixed blocks, and FFTW-MPI's transforms round differently
# from the serial ones: equal to rounding, not bitwise.
kFieldTolerance = 1e-12
# Attributes that record the run rather than the result (present in both,
# values not compared): the solve's wall time, the program's path in the
# command line, and the version with the git hash of the build, which differs
# when the two builds were made at different commits.
kRunAttributes = frozenset({"solve_seconds", "command_line", "halfspace_version"})
# The position of the largest von Mises stress (a /stress group's): a
# symmetric contact has cells whose stresses tie to rounding, of which the
# serial and the distributed programs may report different ones, so these
# are compared by presence and checked by check_von_mises_position.
kVonMisesPosition = frozenset({"max_von_mises_x", "max_von_mises_y", "max_von_mises_z"})
# One process, two, and three (uneven slabs).
kProcessCounts = (1, 2, 3)


class Harness:
    def __init__(self, argv):
        self.arguments = argv[1:6]
        self.mpi_program, self.serial_program, self.mpiexec, self.source_dir, self.work_dir = self.arguments
        # A fresh directory each run: a file an earlier, failed run left
        # behind (the output a refusal case must not write) would fail this
        # run's cases too.
        shutil.rmtree(self.work_dir, ignore_errors=True)
        os.makedirs(self.work_dir)
        self.environment = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                                OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1",
                                HALFSPACE_FFTW_WISDOM="off")
        self.failures = []

    def run(self, command):
        return subprocess.run(command, env=self.environment, capture_output=True, text=True, timeout=300)

    def run_mpi(self, processes, arguments):
        return self.run([self.mpiexec, "--oversubscribe", "-np", str(processes), self.mpi_program] + arguments)

    def fail(self, message):
        print("FAIL: " + message)
        self.failures.append(message)

    def refusal_case(self, name, processes, arguments, message, output, command="solve"):
        """`mpiexec -np processes halfspace COMMAND ARGUMENTS` must exit 1
        (bad input) with one error line containing `message` and write no
        `output`."""
        result = self.run_mpi(processes, [command] + arguments + ["--output", output])
        where = f"{name}, {processes} processes"
        errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
        if result.returncode != kExitInputError:
            self.fail(f"{where}: exit {result.returncode}, expected {kExitInputError}; stderr: {result.stderr.strip()}")
        if len(errors) != 1 or message not in errors[0]:
            self.fail(f"{where}: expected one error line containing {message!r}, got {errors}")
        if os.path.exists(output):
            self.fail(f"{where}: the output {output} was written")
            os.remove(output)  # so that the next case is judged on its own
        print(f"{where}: {errors[0] if errors else result.stderr.strip()}")

    def temporaries(self):
        return [f for f in os.listdir(self.work_dir) if ".tmp-" in f]

    def serial_output(self, name, command, arguments, exit_code=0):
        """The serial program's file for `name` (`command` is solve or
        generate), or None after recording its failure."""
        output = os.path.join(self.work_dir, f"{name}-serial.h5")
        serial = self.run([self.serial_program, command] + arguments + ["--output", output])
        if serial.returncode != exit_code:
            self.fail(f"{name}: the serial program failed ({serial.returncode}): {serial.stderr.strip()}")
            return None
        return output

    def distributed_outputs(self, name, command, arguments, process_counts, exit_code=0):
        """Runs the MPI program on each process count and yields (where,
        file) of each run that exits with `exit_code`, after removing the
        file (and its sweep's CSV) of an earlier run; a run that exits
        otherwise, and temporaries left behind, are recorded as failures."""
        for processes in process_counts:
            output = os.path.join(self.work_dir, f"{name}-np{processes}.h5")
            for path in (output, output[:-3] + ".csv"):
                if os.path.exists(path):
                    os.remove(path)
            distributed = self.run_mpi(processes, [command] + arguments + ["--output", output])
            where = f"{name}, {processes} processes"
            if distributed.returncode != exit_code:
                self.fail(f"{where}: exit {distributed.returncode}, expected {exit_code}: "
                          f"{distributed.stderr.strip()}")
                continue
            yield where, output
            if self.temporaries():
                self.fail(f"{where}: temporaries left behind: {self.temporaries()}")

    def compare_attributes(self, where, got, want, skip, tolerance, absolute=frozenset(), scale=None):
        """Records how the attributes `got` (the distributed file's, a
        mapping) differ from the serial file's `want`: other names; a
        floating-point value beyond `tolerance` times its scale (1 for the
        names in `absolute`, else scale(name) when that gives one, else the
        serial value's size); any other value, or its type, unequal. Names
        in `skip` (the run's, not the result's) are compared by presence."""
        if set(got.keys()) != set(want.keys()):
            self.fail(f"{where}: attributes differ: only distributed {sorted(set(got.keys()) - set(want.keys()))}, "
                      f"only serial {sorted(set(want.keys()) - set(got.keys()))}")
        for name in sorted(set(got.keys()) & set(want.keys())):
            if name in skip:
                continue
            a, b = got[name], want[name]
            if isinstance(b, (float, np.floating)):
                size = 1.0 if name in absolute else (scale(name) if scale else None)
                size = max(abs(float(b)), 1e-300) if size is None else size
                if abs(float(a) - float(b)) > tolerance * size:
                    self.fail(f"{where}: attribute {name} = {a!r}, serial {b!r} (relative {abs(a - b) / size:.2e})")
            elif type(a) is not type(b) or not np.array_equal(np.asarray(a), np.asarray(b)):
                self.fail(f"{where}: attribute {name} = {a!r} ({type(a).__name__}), serial {b!r} "
                          f"({type(b).__name__})")

    def compare_dataset(self, where, name, got, want, tolerance, scale=None):
        """Records how the dataset `got` (h5py, the distributed file's)
        differs from the serial `want`: its shape or type; floating-point
        values beyond `tolerance` times their scale (scale(serial values)
        when that gives one, else the serial values' largest size); other
        values unequal. Returns the floating-point difference over the
        scale (0 for other values)."""
        if got.shape != want.shape or got.dtype != want.dtype:
            self.fail(f"{where}: /{name} is {got.shape} {got.dtype}, serial {want.shape} {want.dtype}")
            return 0.0
        x, y = got[()], want[()]
        if np.issubdtype(y.dtype, np.floating):
            size = scale(y) if scale else None
            if size is None:
                size = max(float(np.max(np.abs(y))), 1e-300) if y.size else 1.0
            error = float(np.max(np.abs(x - y))) / size if y.size else 0.0
            if error > tolerance:
                self.fail(f"{where}: /{name} differs by {error:.2e} of its largest value (allowed {tolerance:.0e})")
            return error
        if not np.array_equal(x, y):
            self.fail(f"{where}: /{name} differs in {int(np.count_nonzero(x != y))} cells")
        return 0.0

    def same_objects(self, where, got, want, required=()):
        """The names of the objects (groups and datasets) of the serial file
        `want` (h5py), or None after recording that the distributed file
        `got` holds others; records the `required` names the serial file
        lacks (the case would not test what it should)."""
        names, got_names = [], []
        want.visit(names.append)
        got.visit(got_names.append)
        if sorted(names) != sorted(got_names):
            self.fail(f"{where}: objects differ: {sorted(got_names)} vs serial {sorted(names)}")
            return None
        missing = [name for name in required if name not in names]
        if missing:
            self.fail(f"{where}: the serial file lacks {missing}: the case does not test what it should")
        return names

    def check_von_mises_position(self, where, got, want):
        """Records unless the serial file `want` (h5py) holds its largest von
        Mises stress, within kFieldTolerance, at the position the distributed
        file `got` reports (a cell centre at a depth of /stress/depths)."""
        if "max_von_mises" not in want.attrs:
            return
        field = want["stress/von_mises"][()]
        depths = want["stress/depths"][()]
        largest = float(want.attrs["max_von_mises"])
        x, y, z = (float(got.attrs[name]) for name in ("max_von_mises_x", "max_von_mises_y", "max_von_mises_z"))
        depth = np.flatnonzero(depths == z)
        column = int(round(x / float(want.attrs["dx"])))
        if depth.size != 1 or not 0 <= column < field.shape[-1]:
            self.fail(f"{where}: the largest von Mises stress at ({x}, {y}, {z}) m is at no cell and depth")
            return
        if field.ndim == 3:
            row = int(round(y / float(want.attrs["dy"])))
            value = float(field[depth[0], row, column]) if 0 <= row < field.shape[1] else -np.inf
        else:
            value = float(field[depth[0], column])
        if not abs(value - largest) <= kFieldTolerance * largest:
            self.fail(f"{where}: the serial von Mises stress at the reported maximum's position ({x}, {y}, {z}) m is "
                      f"{value:.9g} Pa, not the largest {largest:.9g} Pa")

    def finish(self):
        """Exits with 1 after counting the failures recorded, if any."""
        if self.failures:
            print(f"{len(self.failures)} failure(s)")
            sys.exit(1)
