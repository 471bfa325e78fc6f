#!/usr/bin/env python3
"""The weak/strong-scaling model of distributed pk-fourier solves (docs/performance.md,
"Distributed solves"): time per iteration and memory per process of a periodic
N = n x n grid on P MPI processes, from constants measured on one machine
(bench/mpi_scaling.sh) and assumed for the cluster's network.

usage: mpi_cluster_model.py [--check N SECONDS_PER_ITERATION SLAB_MIB]

Per iteration pk-fourier applies K twice and M^-1 once (the solve summaries'
counts: 2 K and 1 M^-1 per iteration), each a forward and a backward FFTW-MPI
transform with one all-to-all transpose each (the spectrum stays transposed):
six all-to-alls, each moving the process's share of the half spectrum,
(n/2 + 1) n / P complex values = 8 N / P bytes, (P - 1)/P of it to other
processes. About twelve small reductions (at most eight doubles per process,
gathered and added in rank order) cost latency only.

The default solver, pk-multilevel, adds its coarse start (distributed while
a level has at least 64 x 64 cells, about a third of a fine solve's work)
and, on grids of 2048^2 and more, block deflation: every process holds the
deflation's contact flags (3 B per cell) and its lists of contact cells
(24 B per contact cell) on its slab and a halo of three block rows, and
solves the coarse problem of N / b^2 blocks itself at each iteration: its
per-block vectors (about 150 B per block) and the rank-order sum of its
right-hand side, which gathers P values of a chunk of 65536 blocks at a
time (8 P x 65536 B). The
last column gives that memory per process (b = 32, 10 % of the cells in
contact); the coarse problem's time is not modelled (at 65536^2 it has 4.2
million blocks, the size of a 2048^2 grid, on every process: use a larger
--deflation-block, or none, at that scale until the coarse problem is
distributed).
"""
import math
import sys

# Measured here (bench/mpi_scaling.sh, serial program, 1 thread, the shared
# 2-core VM under load 6-9): 371 s for 75 iterations at 4096^2, the larger
# of the two grids measured (per cell and log2 N, 2048^2 was 1.7x faster:
# 38.7 s for 59 iterations; large grids are bound by memory traffic).
kSecondsPerCellLog = 371.3 / 75 / (4096**2 * math.log2(4096**2))
# Measured here: a process holds 187 MiB for 2048^2 / 2 cells (read in slabs
# from an HDF5 map, written collectively: the first process holds no more
# than the others), of which 34 MiB is the program itself (a 256^2 run).
kProgramBytes = 34 * 2**20
kSlabBytesPerCell = (187 - 34) * 2**20 / (2048**2 / 2)
# Block deflation on a slab (block_deflation.cpp): contact flags three times
# (this slab's, the fetched and the built, 1 B each per cell) and three
# lists of 8-byte cells over the contact set, taken as 10 % of the cells, on
# the slab and a halo of three block rows; per block of the whole grid, on
# every process, the coarse problem's vectors (near field 9 doubles, counts,
# CG vectors, far-field transform: about 150 B) and the rank-order sum of
# its right-hand side (MpiCommunicator::sum gathers P doubles per value of a
# chunk of 65536).
kDeflationBytesPerCell = 3.0 + 3 * 8 * 0.10
kDeflationBlock = 32
kDeflationHaloBlockRows = 3
kCoarseBytesPerBlock = 150.0
kSumChunk = 65536
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
    """A process's memory with pk-fourier, and with block deflation added."""
    cells = n * n
    slab = kProgramBytes + kSlabBytesPerCell * cells / processes
    blocks = cells / kDeflationBlock**2
    held_cells = cells / processes + kDeflationHaloBlockRows * kDeflationBlock * n
    deflation = (kDeflationBytesPerCell * held_cells + kCoarseBytesPerBlock * blocks +
                 8.0 * processes * min(blocks, kSumChunk))
    return slab, slab + deflation


def table():
    print("| grid | P | iterations | compute s/it | all-to-all s/it (MB per process) | reductions ms/it | "
          "solve time | memory per process | with block deflation |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in (32768, 65536):
        for processes in (16, 32, 64, 128, 256):
            compute, transposes, reductions, volume = seconds_per_iteration(n, processes)
            its = iterations(n)
            total = its * (compute + transposes + reductions)
            slab, deflated = memory(n, processes)
            print(f"| {n}^2 | {processes} | {its:.0f} | {compute:.3f} | {transposes:.3f} ({volume / 1e6:.0f}) | "
                  f"{reductions * 1e3:.2f} | {total / 60:.1f} min | {slab / 2**30:.1f} GiB | {deflated / 2**30:.1f} GiB |")


def check(grid, measured_seconds_per_iteration, measured_slab_mib):
    """The model against a measurement here (bench/mpi_scaling.sh): the serial
    program's time per iteration on one thread, and the memory of each of the
    two processes of the MPI program (pk-fourier)."""
    n = int(grid)
    compute, _, _, _ = seconds_per_iteration(n, 1, cores=1, efficiency=1.0)
    slab, _ = memory(n, 2)
    print(f"{n}^2: model {compute:.2f} s per iteration on one thread, measured {measured_seconds_per_iteration:.2f}; "
          f"two processes: model {slab / 2**20:.0f} MiB each, measured {measured_slab_mib:.0f}")


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "--check":
        check(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
    else:
        table()
