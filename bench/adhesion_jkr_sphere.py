#!/usr/bin/python3
"""The adhesive sphere at a large Tabor parameter against JKR, on grids finer
than a unit test affords (tests/solvers/adhesion_jkr_sphere_test.cpp runs the
two coarsest of the first case): the numbers of docs/validation.md,
"Adhesion".

Each case is one displacement-controlled sweep of `halfspace solve` on a free
grid spanning 3.5 ell (ell = (pi w R^2 / K)^(1/3), K = 4E*/3): loading from
first touch to 0.5 ell^2/R in steps of 0.25, unloading to -0.8 in steps of
0.05. It prints, in pi w R, the largest |P - P_JKR(A)| on each branch
(P_JKR = A^3 - sqrt(6 A^3), A = sqrt(area at the wall / pi) / ell), the
pull-off (the least force of the unloading branch, refined by the parabola
through its neighbours) against JKR's -3/2, the largest difference between
loading and unloading at the approaches both visit (the lattice trapping
the contact edge), and for Maugis-Dugdale also the largest |P - P_Maugis(A)|.

  bench/adhesion_jkr_sphere.py [--halfspace build/bin/halfspace] [--threads 2]
                               [--case exponential:5:64 ...]

A case is LAW:LAMBDA:CELLS_PER_ELL (LAW md or exponential; the exponential
law takes the largest stress of Maugis-Dugdale at LAMBDA, rho = w / sigma0).
The default cases take about 10 minutes on 2 cores.

Needs Debian's python3 with numpy and h5py (scripts/install-deps.sh).
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from adhesion_figures import maugis_curve  # noqa: E402  (Maugis's P(A), the reference's equations)

# R = 1 mm, E* = 1 MPa, w = 0.05 J/m^2.
RADIUS, E_STAR, WORK = 1e-3, 1e6, 0.05
K = 4.0 * E_STAR / 3.0
ELL = (math.pi * WORK * RADIUS**2 / K) ** (1.0 / 3.0)
APPROACH_UNIT = ELL**2 / RADIUS
FORCE_UNIT = math.pi * WORK * RADIUS
WIDTH = 3.5  # ell
# Approaches in twentieths of ell^2/R: loading 0, 0.25, 0.5; unloading to -0.8.
TWENTIETHS = [0, 5, 10] + list(range(9, -17, -1))
DEEPEST = 2

DEFAULT_CASES = [
    "exponential:5:16", "exponential:5:32", "exponential:5:64",
    "exponential:10:32", "exponential:10:64", "exponential:10:128",
    "md:5:32", "md:5:64", "md:5:128",
]


def jkr_load(a_bar):
    return a_bar**3 - math.sqrt(6.0 * a_bar**3)


def refined_minimum(at, values):
    """The least value, refined by the parabola through it and its neighbours."""
    k = int(np.argmin(values))
    if k == 0 or k + 1 >= len(values):
        return values[k]
    (x0, x1, x2), (f0, f1, f2) = at[k - 1:k + 2], values[k - 1:k + 2]
    d01, d12 = (f1 - f0) / (x1 - x0), (f2 - f1) / (x2 - x1)
    curvature = (d12 - d01) / (x2 - x0)
    if not curvature > 0.0:
        return f1
    vertex = 0.5 * (x0 + x1) - d01 / (2.0 * curvature)
    return min(f1 + d01 * (vertex - x1) + curvature * (vertex - x0) * (vertex - x1), f1)


def run_case(program, work, threads, law, lam, cells_per_ell):
    sigma0 = 0.5 * lam * K * ELL / RADIUS
    n = int(round(WIDTH * cells_per_ell))
    size = n * ELL / cells_per_ell
    approaches = [0.05 * k for k in TWENTIETHS]
    adhesion = ["--adhesion-stress", repr(sigma0)] if law == "md" else ["--adhesion-range", repr(WORK / sigma0)]
    result = os.path.join(work, f"{law}_{lam:g}_{cells_per_ell}.h5")
    start = time.monotonic()
    subprocess.run([program, "solve", "--geometry", "sphere", "--radius", repr(RADIUS), "--grid", f"{n}x{n}",
                    "--size", repr(size), "--E-star", repr(E_STAR), "--adhesion", law,
                    "--work-of-adhesion", repr(WORK), *adhesion, "--tol", "1e-6",
                    "--approach=" + ",".join(f"{a * APPROACH_UNIT:.9g}" for a in approaches),
                    "--output", result, "--quiet", "--threads", str(threads)], check=True)
    seconds = time.monotonic() - start
    with h5py.File(result, "r") as f:
        force = f["sweep/total_force"][()] / FORCE_UNIT
        converged = f["sweep/converged"][()]
        # The cells at the wall (gap exactly 0; the sweep's contact_fraction
        # counts the cells of positive pressure instead).
        fraction = np.array([np.mean(f[f"steps/{k:03d}/gap"][()] == 0.0) for k in range(len(force))])
    radius = np.sqrt(fraction * size * size / math.pi) / ELL
    if not converged.all() or (radius == 0.0).any():
        print(f"  {law} lambda {lam:g}, {cells_per_ell} per ell: a step did not converge or lost contact: "
              f"converged {converged.tolist()}, A {np.round(radius, 3).tolist()}")
    error = np.array([p - jkr_load(a) if a > 0.0 else math.nan for p, a in zip(force, radius)])
    hysteresis = max(abs(force[k] - force[j]) for k in range(DEEPEST + 1, len(force)) for j in range(DEEPEST)
                     if TWENTIETHS[j] == TWENTIETHS[k])
    pull_off = refined_minimum(approaches[DEEPEST:], force[DEEPEST:])
    line = (f"{law:11s} lambda {lam:4g} {cells_per_ell:4d}/ell ({n}^2, zone {0.75 / lam**2 * cells_per_ell:.2f} "
            f"cells): |P - P_JKR(A)| loading {np.nanmax(np.abs(error[:DEEPEST + 1])):.3f}, unloading "
            f"{np.nanmax(np.abs(error[DEEPEST:])):.3f}; pull-off {pull_off:.4f} ({100 * (-pull_off / 1.5 - 1):+.1f} %); "
            f"hysteresis {hysteresis:.3f}")
    if law == "md":
        touching = radius > 0.0
        maugis, _ = maugis_curve(lam, radius[touching])
        line += f"; |P - P_Maugis(A)| {np.max(np.abs(force[touching] - maugis)):.3f}"
    print(line + f"; {seconds:.0f} s", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--halfspace", default=os.path.join(ROOT, "build", "bin", "halfspace"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--case", action="append", help="LAW:LAMBDA:CELLS_PER_ELL (repeatable)")
    args = parser.parse_args()
    print(f"Approaches {[round(0.05 * k, 2) for k in TWENTIETHS]} ell^2/R; forces in pi w R; JKR pull-off -1.5")
    with tempfile.TemporaryDirectory() as work:
        for case in args.case or DEFAULT_CASES:
            law, lam, cells = case.split(":")
            if law not in ("md", "exponential"):
                parser.error(f"case {case}: the law must be md or exponential")
            run_case(args.halfspace, work, args.threads, law, float(lam), int(cells))


if __name__ == "__main__":
    main()
