#!/usr/bin/python3
"""Iterations on a growing domain, over several surfaces.

The performance issue asks that the accelerated solver's iterations grow no
faster than logarithmically from 256^2 to 4096^2. One surface per size says
little about that (a single count moves by several iterations from one
realisation to the next), so this solves the same statistical surface for
several seeds at each size and reports, per size, the counts, their mean and
how many of them the block deflation took; then the least-squares fit
mean = a + b log2(side / smallest side) with its residuals, and the increase
per doubling.

Surfaces: `halfspace generate --kind self-affine`, Hurst 0.8, rms slope 0.1,
short cutoff 4 um, a 1 um cell (so the domain grows with the grid and the
statistics stay the same), periodic; E* = 1 GPa, mean pressure 4 MPa (about
8 % of the cells in contact), as in the headline table. Iteration counts
do not depend on the machine's speed (only, by rounding, on the thread
count, which the results file records), so this can run beside other work.

Run it through scripts/growing-domain.sh, which builds the program first.
Needs Debian's python3 with python3-h5py (scripts/install-deps.sh).
"""

import argparse
import datetime
import os
import platform
import shlex
import sys
from pathlib import Path

import h5py

# The headline script's helpers: its directory is this script's.
from headline import EXIT_NOT_CONVERGED, EXIT_OK, ROOT, git, integer_list, run, shown_path, size_list


CELL = 1e-6  # m


class StudyError(Exception):
    """A problem that stops the run; the message says what and where."""


def surface(program, work, side, seed):
    """The seed's surface of side x side cells, generated once and kept."""
    path = work / f"self-affine-{side}-seed{seed}.h5"
    if path.exists():
        return path
    partial = path.with_suffix(".partial.h5")
    done = run([program, "generate", "--kind", "self-affine", "--grid", f"{side}x{side}",
                "--size", side * CELL, "--hurst", 0.8, "--cutoff-short", 4e-6,
                "--rms-slope", 0.1, "--seed", seed, "--quiet", "--output", partial])
    if done.returncode != EXIT_OK:
        raise StudyError(f"generating {path.name} failed (exit {done.returncode}): {done.stderr.strip()}")
    partial.rename(path)
    return path


def solve(program, height_map, result, solver_args):
    done = run([program, "solve", "--height-map", height_map, "--boundary", "periodic", "--E-star", 1e9,
                "--mean-pressure", 4e6, "--quiet", "--output", result, *solver_args])
    if done.returncode not in (EXIT_OK, EXIT_NOT_CONVERGED):
        raise StudyError(f"solving {height_map.name} failed (exit {done.returncode}): {done.stderr.strip()}")
    with h5py.File(result, "r") as f:
        row = {key: f.attrs[key] for key in ("iterations", "deflated_iterations", "converged")}
        # FFT pairs of the whole solve: K and M^-1 products of the fine grid
        # and the coarse levels' work in fine-grid products.
        row["pairs"] = sum(float(f.attrs[key]) for key in ("operator_applications", "preconditioner_applications",
                                                            "coarse_operator_work", "coarse_preconditioner_work")
                           if key in f.attrs)
    result.unlink()
    return row


def log_fit(sides, means):
    """Least squares mean = a + b log2(side / sides[0]): (a, b, residuals)."""
    xs = [s.bit_length() - sides[0].bit_length() for s in sides]
    x_mean = sum(xs) / len(xs)
    y_mean = sum(means) / len(means)
    sxx = sum((x - x_mean) ** 2 for x in xs)
    b = sum((x - x_mean) * (y - y_mean) for x, y in zip(xs, means)) / sxx if sxx > 0 else 0.0
    a = y_mean - b * x_mean
    return a, b, [y - (a + b * x) for x, y in zip(xs, means)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", type=Path, required=True, help="build with bin/halfspace")
    parser.add_argument("--sizes", type=size_list, default=[256, 512, 1024, 2048, 4096],
                        help="grid sides, powers of two [256,512,1024,2048,4096]")
    parser.add_argument("--seeds", type=lambda t: integer_list(t, 0, "seeds"), default=[1, 2, 3, 4, 5],
                        help="surface seeds [1,2,3,4,5]")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--work-dir", type=Path, default=Path("/tmp/halfspace-growing-domain"),
                        help="where the surfaces are kept between runs")
    parser.add_argument("solver_args", nargs="*",
                        help="after --: extra `halfspace solve` options [--deflation-block 32]")
    args = parser.parse_args()

    try:
        sides, seeds = args.sizes, args.seeds
        if not sides or not seeds or any(s & (s - 1) for s in sides):
            raise StudyError(f"--sizes {sides} and --seeds {seeds} are invalid: need at least one of each, "
                             "and every side a power of two")
        program = args.build_dir / "bin" / "halfspace"
        if not os.access(program, os.X_OK):
            raise StudyError(f"{program} is not an executable: build it first (scripts/growing-domain.sh does)")
        solver_args = args.solver_args or ["--deflation-block", "32"]
        solver_args = solver_args + ["--threads", str(args.threads)]
        args.work_dir.mkdir(parents=True, exist_ok=True)

        rows = []
        for side in sides:
            counts, deflated, pairs, failures = [], [], [], 0
            for seed in seeds:
                result = solve(program, surface(program, args.work_dir, side, seed),
                               args.work_dir / f"result-{side}-{seed}.h5", solver_args)
                counts.append(int(result["iterations"]))
                deflated.append(int(result["deflated_iterations"]))
                pairs.append(float(result["pairs"]))
                failures += 0 if int(result["converged"]) else 1
                print(f"{side}^2 seed {seed}: {counts[-1]} iterations ({deflated[-1]} deflated), "
                      f"{pairs[-1]:.1f} FFT pairs", file=sys.stderr)
            rows.append((side, counts, deflated, failures, pairs))
    except StudyError as error:
        print(f"growing-domain: error: {error}", file=sys.stderr)
        return 1

    means = [sum(c) / len(c) for _, c, _, _, _ in rows]
    lines = ["| grid | iterations per seed | mean | deflated (mean) | FFT pairs (mean; K, M^-1 and coarse) | "
             "not converged | fit residual | mean increase over the previous size |",
             "|---|---|--:|--:|--:|--:|--:|--:|"]
    a, b, residuals = log_fit([r[0] for r in rows], means)
    for k, ((side, counts, deflated, failures, pairs), mean, residual) in enumerate(zip(rows, means, residuals)):
        step = f"{mean - means[k - 1]:+.1f}" if k > 0 else ""
        lines.append(f"| {side}x{side} | {', '.join(map(str, counts))} | {mean:.1f} | "
                     f"{sum(deflated) / len(deflated):.1f} | {sum(pairs) / len(pairs):.1f} | {failures} | "
                     f"{residual:+.1f} | {step} |")
    now = datetime.datetime.now(datetime.timezone.utc)
    uname = platform.uname()
    text = "\n".join([
        f"## Growing-domain iterations, {now.strftime('%Y-%m-%dT%H:%M:%SZ')}", "",
        f"- commit: `{git('describe', '--always', '--dirty')}`",
        f"- machine: {uname.system} {uname.release} {uname.machine}, nproc {os.cpu_count()}",
        f"- command: `{shlex.join(['growing_domain.py'] + [shown_path(a) for a in sys.argv[1:]])}`",
        f"- solve options: `{shlex.join(solver_args)}`", "",
        *lines, "",
        f"- fit: mean = {a:.2f} + {b:.2f} log2(side / {rows[0][0]}); "
        f"largest residual {max(abs(r) for r in residuals):.2f}",
        "- surfaces: self-affine, H = 0.8, rms slope 0.1, short cutoff 4 um, 1 um cells, periodic; "
        "E* = 1 GPa, mean pressure 4 MPa", ""])
    print(text)
    commit = git("rev-parse", "--short", "HEAD")
    results = ROOT / "bench" / "results" / f"{now.strftime('%Y-%m-%d')}-{commit}-growing-domain.md"
    with open(results, "a", encoding="utf-8") as out:
        out.write(text + "\n")
    print(f"appended to {results}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
