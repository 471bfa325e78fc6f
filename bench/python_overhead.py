#!/usr/bin/env python3
"""The Python package's call overhead against the program, on the same solve.

For each grid size a self-affine surface is generated once (by the program),
then solved alternately, side by side, by

  * the program: `halfspace solve --height-map F ... --output O` (a process:
    start-up, reading, solving, statistics, writing), and
  * the package in this process: read_height_map(F) + solve(...) +
    Result.save(O) (the same steps as the program), and solve(...) alone on
    the surface already in memory,

with the same threads and FFT planning. Prints the median wall times, the
solve's own time (solve_seconds) and the overhead, wall minus solve_seconds,
of each, with the machine's load.

    bench/python_overhead.py --halfspace build/bin/halfspace --sizes 256 1024 --repeats 5
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import halfspace as hs


def main():
    root = Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--halfspace", type=Path, default=root / "build" / "bin" / "halfspace")
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 1024])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--solver", default="pk-multilevel")
    args = parser.parse_args()
    common = dict(e_star=1e9, mean_pressure=4e6, boundary="periodic", solver=args.solver, tol=1e-10,
                  threads=args.threads, fft_planning="estimate")
    print(f"halfspace {hs.__version__}, {args.threads} thread(s), {args.solver}, estimate planning; "
          f"load average {os.getloadavg()[0]:.2f} at the start")
    print(f"{'n':>5} {'how':<28} {'wall (s)':>9} {'solve (s)':>9} {'overhead (s)':>12}")
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        for n in args.sizes:
            surface = work / f"surface-{n}.h5"
            subprocess.run([str(args.halfspace), "generate", "--kind", "self-affine", "--grid", f"{n}x{n}",
                            "--size", repr(n * 1e-6), "--rms-slope", "0.1", "--seed", "1", "--quiet",
                            "--output", str(surface)], check=True)
            in_memory = hs.read_height_map(surface)
            rows = {"program (process + files)": [], "package: read+solve+save": [], "package: solve only": []}
            for _ in range(args.repeats):
                output = work / "cli.h5"
                start = time.perf_counter()
                subprocess.run([str(args.halfspace), "solve", "--height-map", str(surface), "--E-star", "1e9",
                                "--mean-pressure", "4e6", "--boundary", "periodic", "--solver", args.solver,
                                "--tol", "1e-10", "--threads", str(args.threads), "--fft-planning", "estimate",
                                "--quiet", "--output", str(output)], check=True)
                wall = time.perf_counter() - start
                rows["program (process + files)"].append((wall, hs.read_result(output).solve_seconds))

                start = time.perf_counter()
                result = hs.solve(hs.read_height_map(surface), **common)
                result.save(work / "python.h5")
                rows["package: read+solve+save"].append((time.perf_counter() - start, result.solve_seconds))

                start = time.perf_counter()
                result = hs.solve(in_memory, **common)
                rows["package: solve only"].append((time.perf_counter() - start, result.solve_seconds))
            for how, samples in rows.items():
                wall = statistics.median(s[0] for s in samples)
                solve = statistics.median(s[1] for s in samples)
                overhead = statistics.median(s[0] - s[1] for s in samples)
                print(f"{n:>5} {how:<28} {wall:9.4f} {solve:9.4f} {overhead:12.4f}", flush=True)
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    sys.exit(main())
