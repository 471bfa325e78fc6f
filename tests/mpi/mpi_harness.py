"""What every MPI test script shares: its arguments, the environment the
programs run in (one OpenMP thread, Open MPI allowed to run as root and to
oversubscribe the cores, no FFTW wisdom file, so that plans and results do
not depend on an earlier run), running the serial and the MPI program, and
the list of failures the script reports at its end.

usage in a script: SCRIPT MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR
"""
import os
import subprocess

kExitInputError = 1  # the program's exit code for bad input


class Harness:
    def __init__(self, argv):
        self.arguments = argv[1:6]
        self.mpi_program, self.serial_program, self.mpiexec, self.source_dir, self.work_dir = self.arguments
        os.makedirs(self.work_dir, exist_ok=True)
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

    def refusal_case(self, name, processes, arguments, message, output):
        """`mpiexec -np processes halfspace solve ARGUMENTS` must exit 1 (bad
        input) with one error line containing `message` and write no
        `output`."""
        result = self.run_mpi(processes, ["solve"] + arguments + ["--output", output])
        where = f"{name}, {processes} processes"
        errors = [line for line in result.stderr.splitlines() if line.startswith("error:")]
        if result.returncode != kExitInputError:
            self.fail(f"{where}: exit {result.returncode}, expected {kExitInputError}; stderr: {result.stderr.strip()}")
        if len(errors) != 1 or message not in errors[0]:
            self.fail(f"{where}: expected one error line containing {message!r}, got {errors}")
        if os.path.exists(output):
            self.fail(f"{where}: the output {output} was written")
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
