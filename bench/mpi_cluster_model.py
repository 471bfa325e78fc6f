#!/usr/bin/env python3
"""The weak/strong-scaling model of distributed pk-fourier solves (docs/performance.md,
"Distributed solves"): time per iteration and memory per process of a periodic
N = n x n grid on P MPI processes, from constants measured on one machine
(bench/mpi_scaling.sh) and assumed for the cluster's network.

usage: mpi_cluster_model.py [--check N SECONDS_PER_ITERATION SLAB_MIB FIRST_MIB]

Per iteration pk-fourier applies K twice and M^-1 once (the solve summaries'
counts: 2 K and 1 M^-1 per iteration), each a forward and a backward FFTW-MPI
transform with one all-to-all transpose each (the spectrum stays transposed):
six all-to-alls, each moving the process's share of the half spectrum,
(n/2 + 1) n / P complex values = 8 N / P bytes, (P - 1)/P of it to other
processes. About twelve small reductions (at most eight doubles per process,
gathered and added in rank order) cost latency only. There are no coarse
problems: pk-multilevel and block deflation are not distributed yet.
"""
import math
import sys

# Measured here (bench/mpi_scaling.sh, serial program, 1 thread, the shared
# 2-core VM under load 6-9): 371 s for 75 iterations at 4096^2, the larger
# of the two grids measured (per cell and log2 N, 2048^2 was 1.7x faster:
# 38.7 s for 59 iterations; large grids are bound by memory traffic).
kSecondsPerCellLog = 371.3 / 75 / (4096**2 * math.log2(4096**2))
# Measured here: a process other than the first holds 184 MiB for 2048^2 / 2
# cells, of which 34 MiB is the program itself (a 256^2 run); the first
# process holds 180 MiB more for the whole height map and gathered fields.
kProgramBytes = 34 * 2**20
kSlabBytesPerCell = (184 - 34) * 2**20 / (2048**2 / 2)
kRootBytesPerCell = (364 - 184) * 2**20 / 2048**2
# Iterations of the measured rough surfaces (H = 0.8, rms slope 0.1, 5e7 Pa):
# 59 at 2048^2 and 75 at 4096^2; taken to keep growing by that factor per
# doubling of n.
kIterations2048 = 59
kIterationGrowthPerDoubling = 75 / 59

# Assumed cluster: one MPI process per node of 32 cores used at 60 %, HDR
# InfiniBand (12.5 GB/s per node) reaching half of it in all-to-alls, 2 us
# per message and per reduction step.
kCoresPerProcess = 32
kThreadEfficiency = 0.6
kAllToAllBandwidth = 0.5 * 12.5e9
kMessageLatency = 2e-6
kAllToAllsPerIteration = 6
kReductionsPerIteration = 12


def iterations(n):
    return kIterations2048 * kIterationGrowthPerDoubling ** math.log2(n / 2048)


def seconds_per_iteration(n, processes, cores=kCoresPerProcess, efficiency=kThreadEfficiency,
                          bandwidth=kAllToAllBandwidth, latency=kMessageLatency):
    cells = n * n
    compute = kSecondsPerCellLog * cells * math.log2(cells) / (processes * cores * efficiency)
    volume = 8.0 * cells / processes * (processes - 1) / processes  # bytes sent per all-to-all
    transposes = kAllToAllsPerIteration * (volume / bandwidth + (processes - 1) * latency)
    reductions = kReductionsPerIteration * math.ceil(math.log2(max(processes, 2))) * latency
    return compute, transposes, reductions, volume


def memory(n, processes):
    cells = n * n
    slab = kProgramBytes + kSlabBytesPerCell * cells / processes
    return slab, slab + kRootBytesPerCell * cells


def table():
    print("| grid | P | iterations | compute s/it | all-to-all s/it (MB per process) | reductions ms/it | "
          "solve time | memory per process | first process |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in (32768, 65536):
        for processes in (16, 32, 64, 128, 256):
            compute, transposes, reductions, volume = seconds_per_iteration(n, processes)
            its = iterations(n)
            total = its * (compute + transposes + reductions)
            slab, root = memory(n, processes)
            print(f"| {n}^2 | {processes} | {its:.0f} | {compute:.3f} | {transposes:.3f} ({volume / 1e6:.0f}) | "
                  f"{reductions * 1e3:.2f} | {total / 60:.1f} min | {slab / 2**30:.1f} GiB | {root / 2**30:.0f} GiB |")


def check(grid, measured_seconds_per_iteration, measured_slab_mib, measured_first_mib):
    """The model against a measurement here (bench/mpi_scaling.sh): the serial
    program's time per iteration on one thread, and the memory of the two
    processes of the MPI program."""
    n = int(grid)
    compute, _, _, _ = seconds_per_iteration(n, 1, cores=1, efficiency=1.0)
    slab, root = memory(n, 2)
    print(f"{n}^2: model {compute:.2f} s per iteration on one thread, measured {measured_seconds_per_iteration:.2f}; "
          f"two processes: model {slab / 2**20:.0f} and {root / 2**20:.0f} MiB, measured {measured_slab_mib:.0f} "
          f"and {measured_first_mib:.0f}")


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "--check":
        check(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5]))
    else:
        table()
