#!/usr/bin/python3
"""The headline table: whole `halfspace solve` runs against the bare FFT floor.

For each case (grid, boundary, solver, threads) this runs the real program
under `/usr/bin/time -v`, reads the solver's counters from the result file,
times a bare FFTW r2c + c2r pair of the same transform size with `fft_floor`,
prints a Markdown table and appends it, with the machine and commit, to
bench/results/<date>-<shortcommit>-headline.md.

Cases:
  periodic  self-affine rough surface (`halfspace generate`, Hurst 0.8, rms
            slope 0.1, seed 1), E* = 1 GPa, mean pressure 4 MPa: about 8%
            of the cells in contact
  free      Hertz sphere R = 10 mm, E* = 110 GPa, F = 10 N on a square of
            side 3a (a the Hertz contact radius)

Run it through scripts/headline.sh, which builds the programs first. Needs
Debian's python3 with python3-h5py (scripts/install-deps.sh) and GNU time
(Debian package `time`) for the peak memory.
"""

import argparse
import datetime
import json
import os
import platform
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

import h5py

ROOT = Path(__file__).resolve().parents[2]
GNU_TIME = "/usr/bin/time"

# `halfspace solve` exit codes (apps/exit_codes.hpp): 2 = solved but not
# converged, the result file is still written; anything else is a failure.
EXIT_OK = 0
EXIT_NOT_CONVERGED = 2

# Periodic case: a 1 µm cell, so the surface statistics do not change with n.
PERIODIC_CELL = 1e-6
# Free case: Hertz contact radius a = (3 F R / (4 E*))^(1/3), domain 3a.
HERTZ_RADIUS, HERTZ_E_STAR, HERTZ_FORCE = 0.01, 1.1e11, 10.0
HERTZ_A = (3 * HERTZ_FORCE * HERTZ_RADIUS / (4 * HERTZ_E_STAR)) ** (1 / 3)

# --skip-slow: plain pk above these sizes takes minutes (docs/performance.md).
SLOW_PK_ABOVE = {"periodic": 2048, "free": 1024}


class HeadlineError(Exception):
    """A problem that stops the run; the message says what and where."""


def integer_list(text, smallest, what):
    """'256,512' -> [256, 512]; '' -> []."""
    try:
        values = [int(s) for s in text.split(",") if s.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}': expected a comma list of integers")
    if any(v < smallest for v in values):
        raise argparse.ArgumentTypeError(f"'{text}': {what} must be at least {smallest}")
    return values


def size_list(text):
    """Grid sizes; an empty list means no cases of that boundary."""
    return integer_list(text, 2, "sizes")


def thread_list(text):
    return integer_list(text, 1, "thread counts")


def name_list(text):
    return [s.strip() for s in text.split(",") if s.strip()]


def parse_arguments(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    default_build = os.environ.get("HALFSPACE_BENCH_BUILD_DIR", str(ROOT / "build-bench"))
    p.add_argument("--build-dir", default=default_build,
                   help="build with bin/halfspace and bench/fft_floor [%(default)s]")
    p.add_argument("--solvers", type=name_list, default=name_list("pk,pk-fourier,pk-multilevel"),
                   help="comma list [pk,pk-fourier,pk-multilevel]")
    p.add_argument("--periodic-sizes", type=size_list, default=size_list("256,512,1024,2048"),
                   help="n of the periodic n x n grids, comma list, may be empty [256,512,1024,2048]")
    p.add_argument("--free-sizes", type=size_list, default=size_list("128,256,512"),
                   help="n of the free-boundary n x n grids, comma list, may be empty [128,256,512]")
    p.add_argument("--threads", type=thread_list, default=[2], help="comma list [2]")
    p.add_argument("--planning", choices=["estimate", "measure", "patient"], default="measure",
                   help="FFTW planning of the solves and of the floor [%(default)s]")
    p.add_argument("--skip-slow", action="store_true",
                   help="skip pk above 2048^2 periodic and 1024^2 free")
    p.add_argument("--out-dir", default=str(ROOT / "bench" / "results"),
                   help="directory of the results file [%(default)s]")
    return p.parse_args(argv)


def shown_path(argument: str) -> str:
    """An argument as the results file records it: a path outside the
    project as '<dir>/name' (machine paths do not belong in results)."""
    path = Path(argument)
    if not path.is_absolute():
        return argument
    try:
        return str(path.resolve().relative_to(ROOT.resolve()))
    except ValueError:
        return f"<dir>/{path.name}"


def shown(command):
    return shlex.join(map(str, command))


def run(command, **kwargs):
    return subprocess.run(list(map(str, command)), capture_output=True, text=True, **kwargs)


def check_output(command, what, **kwargs):
    """stdout of a command that must succeed; HeadlineError naming `what` if not."""
    done = run(command, **kwargs)
    if done.returncode != 0:
        raise HeadlineError(f"{what} failed (exit code {done.returncode}): {shown(command)}\n"
                            f"{done.stderr.strip()}")
    return done.stdout


def check_gnu_time():
    if not os.access(GNU_TIME, os.X_OK):
        raise HeadlineError(f"{GNU_TIME} not found: the peak memory needs GNU time "
                            "(Debian package `time`, scripts/install-deps.sh)")
    # bash's `time` keyword and BSD time have no -v; GNU time does.
    if run([GNU_TIME, "-v", "true"]).returncode != 0:
        raise HeadlineError(f"{GNU_TIME} -v failed: GNU time is needed (Debian package `time`)")


# ---------------------------------------------------------------- cases


def periodic_size(n):
    return f"{n * PERIODIC_CELL:.6g}"


def solve_command(halfspace, case, solver, threads, planning, output):
    n = case["n"]
    if case["boundary"] == "periodic":
        surface = ["--height-map", case["surface"], "--boundary", "periodic",
                   "--E-star", "1e9", "--mean-pressure", "4e6"]
    else:
        surface = ["--geometry", "sphere", "--radius", f"{HERTZ_RADIUS:g}", "--grid", f"{n}x{n}",
                   "--size", f"{3 * HERTZ_A:.6g}", "--boundary", "free",
                   "--E-star", f"{HERTZ_E_STAR:g}", "--force", f"{HERTZ_FORCE:g}"]
    return [halfspace, "solve", *surface, "--solver", solver, "--threads", str(threads),
            "--fft-planning", planning, "--output", str(output), "--quiet"]


def generate_surface(halfspace, n, directory, env):
    path = directory / f"surface-{n}.h5"
    check_output([halfspace, "generate", "--kind", "self-affine", "--grid", f"{n}x{n}",
                  "--size", periodic_size(n), "--hurst", "0.8", "--cutoff-short", "4e-6",
                  "--rms-slope", "0.1", "--seed", "1", "--output", str(path), "--quiet"],
                 f"halfspace generate {n}x{n}", env=env)
    return str(path)


def peak_rss_bytes(time_report):
    for line in time_report.splitlines():
        if "Maximum resident set size" in line:
            return int(line.rsplit(":", 1)[1]) * 1024  # GNU time reports kbytes
    raise HeadlineError(f"no 'Maximum resident set size' in the output of {GNU_TIME} -v:\n{time_report}")


def timed_solve(halfspace, case, solver, threads, planning, directory, env):
    output = directory / "out.h5"
    time_report = directory / "time.txt"
    output.unlink(missing_ok=True)
    command = solve_command(halfspace, case, solver, threads, planning, output)
    done = run([GNU_TIME, "-v", "-o", str(time_report), *command], env=env)
    if done.returncode not in (EXIT_OK, EXIT_NOT_CONVERGED):
        raise HeadlineError(f"solve failed (exit code {done.returncode}): {shown(command)}\n"
                            f"{done.stderr.strip()}")
    row = {"peak_bytes": peak_rss_bytes(time_report.read_text())}
    with h5py.File(output, "r") as f:
        attrs = f.attrs
        for key in ("iterations", "operator_applications", "preconditioner_applications",
                    "solve_seconds", "converged", "residual", "contact_fraction"):
            if key not in attrs:
                raise HeadlineError(f"{output}: attribute '{key}' missing (from: {shown(command)})")
            row[key] = attrs[key].item()
        # Written since pk-multilevel; older builds have no coarse grids.
        for key in ("coarse_operator_work", "coarse_preconditioner_work"):
            row[key] = attrs[key].item() if key in attrs else 0.0
    row["exit_code"] = done.returncode
    return row


def fft_floor(tool, n, threads, planning, padded):
    # Timed again after every solve, not once per grid: this VM's speed
    # drifts by up to 2x within minutes, and a floor taken in another state
    # than the solve moved the ratio by as much (docs/performance.md).
    command = [tool, "--n", str(n), "--threads", str(threads), "--planning", planning]
    if padded:
        command.append("--padded")
    return json.loads(check_output(command, f"fft_floor {n} threads {threads}"))


# ---------------------------------------------------------------- table

COLUMNS = ["grid", "boundary", "solver", "threads", "iterations", "K", "M^-1",
           "coarse (K+M^-1 equivalents)", "solve s", "s per K", "iteration / FFT pair", "FFT pair ms",
           "peak MiB", "B/point"]


def table_row(r):
    n = r["n"]
    solver = r["solver"]
    if not r["converged"]:
        solver += f" **NOT CONVERGED** (residual {r['residual']:.2g})"
    seconds = r["solve_seconds"]
    k = r["operator_applications"]
    iterations = r["iterations"]
    coarse = r["coarse_operator_work"] + r["coarse_preconditioner_work"]
    per_iteration = seconds / iterations / r["floor"]["seconds_per_pair"] if iterations else float("nan")
    cells = [f"{n}x{n}", r["boundary"], solver, str(r["threads"]), str(iterations), str(k),
             str(r["preconditioner_applications"]), f"{coarse:.1f}", f"{seconds:.3g}",
             f"{seconds / k:.3g}" if k else "–", f"{per_iteration:.2f}",
             f"{1e3 * r['floor']['seconds_per_pair']:.3g}",
             f"{r['peak_bytes'] / 2**20:.1f}", f"{r['peak_bytes'] / (n * n):.0f}"]
    return "| " + " | ".join(cells) + " |"


def markdown_table(rows):
    lines = ["| " + " | ".join(COLUMNS) + " |",
             "|" + "|".join(["---"] * 3 + ["--:"] * (len(COLUMNS) - 3)) + "|"]
    return "\n".join(lines + [table_row(r) for r in rows])


def footnotes(args):
    planning = (f"Plans made with `--fft-planning {args.planning}` from a fresh FFTW wisdom file per run "
                "(HALFSPACE_FFTW_WISDOM in a temporary directory), never the user's cache.")
    return "\n".join([
        "- solve s: the solver's own wall time (HDF5 attribute solve_seconds). Every FFT plan is made before "
        "it starts, pk-multilevel's coarse grids included (it plans them when it is built and rebuilds "
        "them from the wisdom inside the solve), so planning is excluded; so are reading and writing files.",
        "- " + planning,
        "- K, M^-1: fine-grid operator and preconditioner applications (one FFT pair each, the free "
        "boundary's K on the 2n x 2n padded grid). coarse: pk-multilevel's coarse-grid K + M^-1 products "
        "weighted by cells (fine-grid equivalents), not included in K or M^-1.",
        "- s per K: solve s / K, so it also carries the M^-1 products, the coarse grids and the "
        "vector work of each iteration.",
        "- iteration / FFT pair: (solve s / iterations) / one bare out-of-place FFTW r2c + c2r pair of the "
        "same transform (n x n periodic, 2n x 2n free; `fft_floor`, same threads and planning), timed "
        "right after each solve; FFT pair ms: that pair.",
        "- peak MiB, B/point: maximum resident set size of the whole `halfspace solve` process "
        "(`/usr/bin/time -v`): program, libraries, surface, result fields and HDF5 output buffer "
        "included, so small grids are dominated by the fixed part.",
        "- Cases: periodic = self-affine surface (`halfspace generate --kind self-affine --size n µm "
        "--hurst 0.8 --cutoff-short 4e-6 --rms-slope 0.1 --seed 1`), E* = 1 GPa, mean pressure 4 MPa; "
        f"free = Hertz sphere R = {HERTZ_RADIUS:g} m, E* = {HERTZ_E_STAR:g} Pa, F = {HERTZ_FORCE:g} N, "
        f"domain 3a = {3 * HERTZ_A:.4g} m. Tolerance: the program's default.",
    ])


# ---------------------------------------------------------------- machine


def git(*arguments):
    done = run(["git", "-C", str(ROOT), *arguments])
    return done.stdout.strip() if done.returncode == 0 and done.stdout.strip() else "unknown"


def cpu_model():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def load_average():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


# ---------------------------------------------------------------- main


def cases(args, halfspace, directory, env):
    """(case, solver) in the order they run; surfaces generated on the way."""
    for boundary, sizes in (("periodic", args.periodic_sizes), ("free", args.free_sizes)):
        for n in sizes:
            case = {"n": n, "boundary": boundary}
            if boundary == "periodic":
                case["surface"] = generate_surface(halfspace, n, directory, env)
            solvers = [s for s in args.solvers
                       if not (args.skip_slow and s == "pk" and n > SLOW_PK_ABOVE[boundary])]
            yield case, solvers


def main(argv):
    args = parse_arguments(argv)
    if not args.solvers:
        raise HeadlineError("--solvers: no solver given")
    if not args.threads:
        raise HeadlineError("--threads: no thread count given")
    build = Path(args.build_dir)
    halfspace = build / "bin" / "halfspace"
    floor_tool = build / "bench" / "fft_floor"
    for program in (halfspace, floor_tool):
        if not os.access(program, os.X_OK):
            raise HeadlineError(f"{program} not found: build it first (scripts/headline.sh does)")
    check_gnu_time()

    started = datetime.datetime.now(datetime.timezone.utc)
    load_before = load_average()
    rows = []
    with tempfile.TemporaryDirectory(prefix="halfspace-headline-") as temporary:
        directory = Path(temporary)
        env = dict(os.environ, HALFSPACE_FFTW_WISDOM=str(directory / "wisdom"))
        for case, solvers in cases(args, halfspace, directory, env):
            n, boundary = case["n"], case["boundary"]
            for threads in args.threads:
                for solver in solvers:
                    row = timed_solve(halfspace, case, solver, threads, args.planning, directory, env)
                    row.update(n=n, boundary=boundary, solver=solver, threads=threads)
                    row["floor"] = fft_floor(floor_tool, n, threads, args.planning, boundary == "free")
                    rows.append(row)
                    status = "converged" if row["converged"] else "NOT CONVERGED"
                    print(f"headline: {n}x{n} {boundary} {solver} threads {threads}: {row['iterations']} iterations, "
                          f"{row['solve_seconds']:.3g} s, contact {100 * row['contact_fraction']:.1f}%, {status}",
                          file=sys.stderr, flush=True)

    table = markdown_table(rows)
    print(table)
    not_converged = sum(1 for r in rows if not r["converged"])
    if not_converged:
        print(f"\n{not_converged} run(s) did NOT converge (marked in the table)")

    commit = git("rev-parse", "--short", "HEAD")
    nproc = len(os.sched_getaffinity(0))
    uname = platform.uname()
    header = "\n".join([
        f"## Headline solves, {started.strftime('%Y-%m-%dT%H:%M:%SZ')}",
        "",
        f"- commit: `{git('describe', '--always', '--dirty')}`",
        f"- machine: {uname.system} {uname.release} {uname.machine}, nproc {nproc}, cpu {cpu_model()}",
        f"- load: {load_before} (1, 5, 15 min) before the run, {load_average()} after (includes the run)",
        f"- command: `{shlex.join(['headline.py', *(shown_path(a) for a in argv)])}`",
    ])
    out_dir = Path(args.out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    results = out_dir / f"{started.strftime('%Y-%m-%d')}-{commit}-headline.md"
    with open(results, "a", encoding="utf-8") as f:
        f.write(f"{header}\n\n{table}\n\n{footnotes(args)}\n\n")
    print(f"\nappended to {results}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except HeadlineError as error:
        print(f"headline: error: {error}", file=sys.stderr)
        sys.exit(1)
