#!/usr/bin/env python3
"""Subsurface stresses at a list of depths against one solve of the same
contact (issue 20's performance target), for a homogeneous and a coated
half-space, through the Python package (the library's compute, no file).

One phase per process, so that each peak resident memory is its own:

  * solve: a self-affine periodic surface (H = 0.8, rms slope 0.1, mean
    pressure 0.02 E* h'rms, the default solver), generated and solved;
  * stress: the same, then halfspace.subsurface_stress at the depths;
  * coated: the same on a hard coating (t = 5 um, E1 = 3 E2), then its
    stresses (the per-mode layered solution).

Prints wall times (the solve's own solve_seconds, the stress call) and the
peak resident memory of each phase, with the machine's load.

    build/python-venv/bin/python bench/stress_bench.py --size 2048 --depths 16 --threads 1
"""
import argparse
import os
import resource
import subprocess
import sys
import time

E_STAR = 1e9  # Pa
NU = 0.3
COATING = {"thickness": 5e-6, "layer_E": 3 * 0.91e9, "layer_nu": 0.3, "substrate_E": 0.91e9, "substrate_nu": 0.3}


def phase(name, size, depth_count, threads):
    import numpy as np

    import halfspace as hs

    surface = hs.generate.self_affine(grid=(size, size), size=size * 1e-6, hurst=0.8, cutoff_short=4e-6,
                                      rms_slope=0.1, seed=1)
    material = {"coating": COATING} if name == "coated" else {"e_star": E_STAR}
    result = hs.solve(surface, boundary="periodic", mean_pressure=2e6, threads=threads, **material)
    line = f"{name}: {size}^2, solve {result.solve_seconds:.2f} s ({result.iterations} iterations)"
    if name != "solve":
        depths = list(np.linspace(1e-6, 3e-5, depth_count))
        start = time.perf_counter()
        field = hs.subsurface_stress(result, depths, None if name == "coated" else NU)
        seconds = time.perf_counter() - start
        line += (f", stresses at {depth_count} depths {seconds:.2f} s ({seconds / result.solve_seconds:.2f} x the "
                 f"solve), max von Mises {field['max_von_mises'] / 1e6:.2f} MPa")
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024 ** 2  # KiB -> GiB
    print(f"{line}, peak memory {peak:.2f} GiB", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=2048)
    parser.add_argument("--depths", type=int, default=16)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--phase", choices=("solve", "stress", "coated"))
    args = parser.parse_args()
    if args.phase:
        phase(args.phase, args.size, args.depths, args.threads)
        return
    print(f"load average {os.getloadavg()}, {os.cpu_count()} CPUs")
    for name in ("solve", "stress", "coated"):
        subprocess.run([sys.executable, __file__, "--phase", name, "--size", str(args.size), "--depths",
                        str(args.depths), "--threads", str(args.threads)], check=True)
    print(f"load average {os.getloadavg()}")


if __name__ == "__main__":
    main()
