"""What every MPI test script shares: its arguments, the environment the
programs run in (one OpenMP thread, Open MPI allowed to run as root and to
oversubscribe the cores, no FFTW wisdom file, so that plans and results do
not depend on an earlier run), running the serial and the MPI program, and
the list of failures the script reports at its end.

usage in a script: SCRIPT MPI_PROGRAM SERIAL_PROGRAM MPIEXEC SOURCE_DIR WORK_DIR
"""
import os
import subprocess


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
