#!/usr/bin/env python3
"""halfspace against Tamaas's Polonsky-Keer solver on the same rough surfaces.

For each grid size a periodic self-affine surface is generated with
`halfspace generate` and solved under the same mean pressure by
  * Tamaas's PolonskyKeerRey (plain Polonsky-Keer, Rey et al. 2017),
  * halfspace `--solver pk` (plain Polonsky-Keer: the same algorithm),
  * halfspace `--solver pk-fourier` (Fourier-preconditioned),
  * halfspace `--solver pk-multilevel` (the default: pk-fourier started from coarser grids),
and the script prints iterations, FFT pairs, seconds and the ratios
Tamaas / halfspace.

Matching the tolerances. The two codes stop on different measures: Tamaas on
its complementarity error (sum p g over the load times the rms height, about
sum_i p_i g_i / (sum_i p_i * rms(h))), halfspace on its residual
(sum_i p_i |g_i| / (sum_i p_i * g_ref) plus the interpenetration, g_ref =
ptp(g0) + ptp(K p); docs/theory.md). Both are zero exactly at the solution,
but their scales differ by ptp/rms, about 10. So the halfspace residual of
Tamaas's own final (pressure, gap, displacement) is computed here, and
Tamaas's tolerance is tightened in steps of sqrt(10) from 100 x TOL until
that residual is at most TOL: both codes then meet the same stopping test. As a
check that they solve the same discrete problem to the same accuracy, every
pressure field is compared with a reference (halfspace pk-fourier at
tolerance 1e-13): relative L2 difference `dp_ref`.

Tamaas is optional: where `import tamaas` fails the script says so and exits
0. scripts/compare-tamaas.sh installs it in a virtual environment.

    bench/compare_tamaas.py --halfspace build/bin/halfspace --sizes 256 512 1024

halfspace is called through its Python package where `import halfspace`
works (the same library call as the program's, without its files), else
through the program; the program still generates the surfaces.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

try:
    import h5py
    import numpy as np
except ImportError as error:  # pragma: no cover - depends on the machine
    print(f"compare_tamaas: skipped, {error.name} is not installed (pip install numpy h5py)")
    sys.exit(0)

try:
    import tamaas as tm
except ImportError:
    print("compare_tamaas: skipped, Tamaas is not installed (pip install tamaas, or scripts/compare-tamaas.sh)")
    sys.exit(0)

# halfspace itself: through the Python package (pip install .) where it is
# installed, in this process; else through the program and its files.
try:
    import halfspace as halfspace_package
except ImportError:
    halfspace_package = None

# The reference solution's tolerance: near the rounding floor of the residual.
REFERENCE_TOL = 1e-13
# Tamaas tolerances tried, as multiples of TOL, loosest first (steps of
# sqrt(10), so that the residual reached is within that factor of TOL).
TAMAAS_TOL_FACTORS = tuple(10.0 ** (k / 2) for k in range(4, -5, -1))


def halfspace_residual(p, g, u, g0):
    """halfspace's stopping measure (docs/theory.md) of any (p, g, K p)."""
    pbar = p.mean()
    g_ref = np.ptp(g0) + np.ptp(u)
    contact = np.sum(p / pbar * np.abs(g)) if pbar > 0 else 0.0
    return (contact + np.sum(np.maximum(-g, 0.0))) / (p.size * g_ref)


def relative_difference(p, reference):
    return float(np.linalg.norm(p - reference) / np.linalg.norm(reference))


def last_iteration(lines):
    """Tamaas logs 'iteration cost error' rows; the last one is the final iteration."""
    for line in reversed(lines):
        fields = line.split()
        if len(fields) == 3 and fields[0].isdigit():
            return int(fields[0])
    return -1


def tamaas_worker(surface, e_star, mean_pressure, tol, pressure_file):
    """Runs in a child process (--tamaas-worker): solves with Tamaas, saves the
    pressure, prints 'RESULT seconds error residual'. Tamaas writes its log,
    which gives the iteration count, from C++ to standard error, where the
    parent collects it."""
    with h5py.File(surface, "r") as f:
        heights = f["height"][...]
        dx, dy = float(f.attrs["dx"]), float(f.attrs["dy"])
    ny, nx = heights.shape
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [ny * dy, nx * dx], [ny, nx])
    model.E = e_star  # E* = E / (1 - nu^2) with nu = 0
    model.nu = 0.0
    solver = tm.PolonskyKeerRey(model, heights, tol)
    solver.max_iter = 1000000
    start = time.perf_counter()
    error = solver.solve(mean_pressure)
    seconds = time.perf_counter() - start
    p = np.array(model.traction)
    residual = halfspace_residual(p, np.array(model["gap"]), np.array(model.displacement), heights.max() - heights)
    np.save(pressure_file, p)
    print(f"RESULT {float(seconds)!r} {float(error)!r} {float(residual)!r}", flush=True)


def solve_tamaas(surface, workdir, e_star, mean_pressure, tol):
    pressure_file = workdir / "tamaas-pressure.npy"
    command = [sys.executable, __file__, "--tamaas-worker", str(surface), repr(e_star), repr(mean_pressure),
               repr(tol), str(pressure_file)]
    child = subprocess.run(command, check=True, capture_output=True, text=True)
    result = next(line.split() for line in child.stdout.splitlines() if line.startswith("RESULT "))
    pressure = np.load(pressure_file)
    pressure_file.unlink()
    return {
        "iterations": last_iteration(child.stderr.splitlines()),
        "fft_pairs": None,  # not reported by Tamaas
        "seconds": float(result[1]),
        "own_error": float(result[2]),
        "residual": float(result[3]),
        "pressure": pressure,
    }


def solve_halfspace(exe, surface, workdir, solver, e_star, mean_pressure, tol, threads, planning):
    """Solves through the Python package where it is installed (in this
    process, no files), else through the program."""
    if halfspace_package is not None:
        return solve_halfspace_package(surface, workdir, solver, e_star, mean_pressure, tol, threads, planning)
    return solve_halfspace_cli(exe, surface, workdir, solver, e_star, mean_pressure, tol, threads, planning)


def result_row(attributes, pressure):
    return {
        "iterations": int(attributes["iterations"]),
        # pk-multilevel's coarse grids count in products of this grid, rounded.
        "fft_pairs": int(attributes["operator_applications"])
        + int(attributes.get("preconditioner_applications", 0))
        + round(float(attributes.get("coarse_operator_work", 0.0))
                + float(attributes.get("coarse_preconditioner_work", 0.0))),
        "seconds": float(attributes["solve_seconds"]),
        "own_error": float(attributes["residual"]),
        "residual": float(attributes["residual"]),
        "pressure": pressure,
        "contact_fraction": float(attributes["contact_fraction"]),
    }


def solve_halfspace_package(surface, workdir, solver, e_star, mean_pressure, tol, threads, planning):
    hs = halfspace_package
    # solve_seconds excludes planning; the wisdom stays in the work directory
    # (read by the library when it plans, so setting it here is in time).
    os.environ["HALFSPACE_FFTW_WISDOM"] = str(workdir / "fftw-wisdom")
    result = hs.solve(hs.read_height_map(surface), e_star=e_star, mean_pressure=mean_pressure,
                      boundary="periodic", solver=solver, tol=tol, max_iter=1000000, threads=threads,
                      fft_planning=planning)
    return result_row(result.attributes, result.pressure)


def solve_halfspace_cli(exe, surface, workdir, solver, e_star, mean_pressure, tol, threads, planning):
    output = workdir / f"{surface.stem}-{solver}-{tol:g}.h5"
    command = [str(exe), "solve", "--height-map", str(surface), "--boundary", "periodic",
               "--E-star", repr(e_star), "--mean-pressure", repr(mean_pressure), "--solver", solver,
               "--tol", repr(tol), "--max-iter", "1000000", "--threads", str(threads),
               "--fft-planning", planning, "--quiet", "--output", str(output)]
    # solve_seconds excludes planning; the wisdom stays in the work directory.
    environment = dict(os.environ, HALFSPACE_FFTW_WISDOM=str(workdir / "fftw-wisdom"))
    # Exit code 2 (not converged) still writes the result: the reference at
    # 1e-13 may stop a little short of it, which the dp columns then show.
    if subprocess.run(command, env=environment).returncode not in (0, 2):
        sys.exit(f"compare_tamaas: {' '.join(command)} failed")
    with h5py.File(output, "r") as f:
        result = result_row(dict(f.attrs), f["pressure"][...])
    output.unlink()
    return result


def generate_surface(exe, n, args, workdir):
    surface = workdir / f"surface-{n}.h5"
    if not surface.exists():
        subprocess.run([str(exe), "generate", "--kind", "self-affine", "--grid", f"{n}x{n}",
                        "--size", repr(n * args.dx), "--hurst", repr(args.hurst),
                        "--cutoff-short", repr(4 * args.dx), "--rms-slope", repr(args.rms_slope),
                        "--seed", str(args.seed), "--quiet", "--output", str(surface)], check=True)
    return surface


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    root = Path(__file__).resolve().parent.parent
    parser.add_argument("--halfspace", type=Path, default=root / "build" / "bin" / "halfspace",
                        help="the halfspace program [build/bin/halfspace]")
    parser.add_argument("--sizes", type=int, nargs="+", default=[256, 512, 1024])
    parser.add_argument("--tol", type=float, default=1e-10, help="halfspace's tolerance [1e-10]")
    parser.add_argument("--E-star", dest="e_star", type=float, default=1e9)
    parser.add_argument("--mean-pressure", type=float, default=4e6,
                        help="Pa [4e6: about 8%% contact at rms slope 0.1]")
    parser.add_argument("--hurst", type=float, default=0.8)
    parser.add_argument("--rms-slope", type=float, default=0.1)
    parser.add_argument("--dx", type=float, default=1e-6, help="spacing (m) [1e-6]")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=1,
                        help="halfspace threads [1: the PyPI build of Tamaas is serial]")
    parser.add_argument("--fft-planning", default="measure", choices=["estimate", "measure", "patient"],
                        help="halfspace's FFT planning [measure, its default]")
    parser.add_argument("--workdir", type=Path, help="where surfaces are kept [a temporary directory]")
    args = parser.parse_args()
    if not args.halfspace.exists():
        sys.exit(f"compare_tamaas: {args.halfspace} not found: build halfspace or pass --halfspace")

    info = tm.TamaasInfo
    via = "the Python package" if halfspace_package is not None else str(args.halfspace)
    print(f"Tamaas {info.version} (backend {info.backend}); halfspace through {via}; "
          f"tol {args.tol:g}; {args.threads} halfspace thread(s), FFT planning {args.fft_planning}; "
          f"load {os.getloadavg()[0]:.2f}")
    header = (f"{'n':>5} {'code':<22} {'tol':>7} {'iter':>6} {'FFT pairs':>9} {'seconds':>9} "
              f"{'residual':>9} {'dp_ref':>9}  T/h time  T/h iter")
    print(header)
    with tempfile.TemporaryDirectory() as temporary:
        workdir = args.workdir or Path(temporary)
        workdir.mkdir(parents=True, exist_ok=True)
        for n in args.sizes:
            surface = generate_surface(args.halfspace, n, args, workdir)
            run = lambda solver, tol: solve_halfspace(args.halfspace, surface, workdir, solver, args.e_star,
                                                      args.mean_pressure, tol, args.threads, args.fft_planning)
            reference = run("pk-fourier", REFERENCE_TOL)["pressure"]
            rows = {"halfspace pk": run("pk", args.tol), "halfspace pk-fourier": run("pk-fourier", args.tol),
                    "halfspace pk-multilevel": run("pk-multilevel", args.tol)}
            for factor in TAMAAS_TOL_FACTORS:
                tamaas = solve_tamaas(surface, workdir, args.e_star, args.mean_pressure, factor * args.tol)
                tamaas["tol"] = factor * args.tol
                if tamaas["residual"] <= args.tol:
                    break
            rows = {"tamaas PolonskyKeerRey": tamaas, **rows}
            for name, row in rows.items():
                tol = row.get("tol", args.tol)
                ratios = ""
                if not name.startswith("tamaas"):
                    ratios = (f"  {tamaas['seconds'] / row['seconds']:8.2f}"
                              f"  {tamaas['iterations'] / row['iterations']:8.2f}")
                pairs = "-" if row["fft_pairs"] is None else row["fft_pairs"]
                print(f"{n:>5} {name:<22} {tol:7.1e} {row['iterations']:>6} {pairs:>9} "
                      f"{row['seconds']:>9.3f} {row['residual']:9.2e} "
                      f"{relative_difference(row['pressure'], reference):9.2e}{ratios}", flush=True)


if __name__ == "__main__":
    if len(sys.argv) == 7 and sys.argv[1] == "--tamaas-worker":
        surface, e_star, mean_pressure, tol, pressure_file = sys.argv[2:]
        tamaas_worker(surface, float(e_star), float(mean_pressure), float(tol), pressure_file)
    else:
        main()
