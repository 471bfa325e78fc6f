#!/usr/bin/python3
"""The robustness matrix of the interface laws (issue 32, "Keep it found"):
the `halfspace` program run over measured maps x boundary x law x load, each
run either converged, with its result checked apart from the solver, or
refused up front with a message; anything else is FAILED.

  bench/robustness_matrix.py [--halfspace build/bin/halfspace] [--jobs 2]
                             [--markdown matrix.md] [--quick] [MAP ...]

Maps: the 2D height maps (`*.h5`, rank 2) in ../shared/data/topography beside
the project root ($SHARED overrides ../shared), or the files given; each is
cut to its central --window x --window cells (smaller maps whole), filled
where the instrument marked points invalid, and detrended by a plane.
Boundaries: periodic and free. E* = 1 GPa throughout (the laws' parameters
scale with it, so nothing depends on its value).

Loads. For each map and boundary, three mean pressures p1, p2, p3 giving
about 1 %, 5 % and 20 % elastic contact area, found by plain solves (a
secant on log p against log area, started from the rough-surface estimate
area = 2 p / (E* h'rms)); those plain solves are the matrix's `elastic` rows,
and their approaches are the displacement-controlled loads. With p_c the
mean contact pressure of the 5 % solve (p2 over its area):

  hardness-high   H = 4 p_c (caps a few % of the contact)
  hardness-low    H = p_c   (caps much of it)
  md-force        Maugis-Dugdale, sigma0 = p_c / 2, h0 = 4 dx sigma0 / E*
                  (a cohesive zone of a few cells), under --mean-pressure
  md-approach     the same under --approach
  exp-force       exponential law, the same w and rho = h0, --mean-pressure
  exp-approach    the same under --approach
  coat-soft       a layer of thickness 10 dx whose plane-strain modulus is
                  E*, on a substrate 10 times stiffer (layer E / substrate
                  E = 0.1), --mean-pressure
  coat-hard       the same layer on a substrate 1000 times softer (1e3)

Checks of a converged result, from its fields alone (tolerances relative to
the largest |pressure| p_ref and to the gap scale g_ref = ptp(height) +
ptp(displacement), that of the Polonsky-Keer residual (polonsky_keer.hpp); the
solvers stop at 1e-10 (Polonsky-Keer) and 1e-6 (adhesive) of their own
residuals, these are looser by 10^2 or more):

  finite      every field is finite
  gap         gap - displacement + approach + height is one constant (the
              definition of the gap), to 1e-8 of the largest of its terms
  force       sum p dx dy equals total_force (to 1e-9 of sum |p| dx dy), and
              the prescribed mean pressure or approach is met (mean pressure
              to 1e-5 relative: the adhesive search's force tolerance is 1e-6)
  bounds      p >= 0 (elastic, coatings); 0 <= p <= H (hardness), to 1e-9
              of p_ref; p >= -sigma0 (md) or -w/rho (exponential), to 1e-5
              of p_ref (the adhesive solver's residual is 1e-6 of p_ref)
  law         no penetration outside the cap (gap >= -1e-6 g_ref); no
              pressure off the wall: sum p+ |gap| dA / (sum p+ dA g_ref)
              <= 1e-6 (complementarity); the plastic cells are those at
              p = H and not above the wall; off the wall the adhesive
              traction is the law's, |p - t(gap)| <= 1e-4 p_ref (md: cells
              within 1e-6 g_ref of h0 may take any value in [-sigma0, 0])

Outcome per run: `converged` (exit 0, `converged` = 1, every check holds),
`refused` (exit 1, apps/exit_codes.hpp, before solving: no result file and a
message on stderr), `FAILED` otherwise (exit 2 or another code, a timeout, or
a failed check). Prints the matrix and the counts per law, writes them as
Markdown to --markdown, and exits 1 if any run FAILED.

--quick (the ctest): two maps at 64 x 64 (from ../shared, or without it the
crops in tests/data), the 5 % load only.

Needs Debian's python3 with numpy and h5py (scripts/install-deps.sh).
"""

import argparse
import concurrent.futures
import math
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
E_STAR = 1e9
NU = 0.3
TARGET_AREAS = (0.01, 0.05, 0.2)
LAWS = ("elastic", "hardness-high", "hardness-low", "md-force", "md-approach", "exp-force", "exp-approach",
        "coat-soft", "coat-hard")
EXIT_OK, EXIT_INPUT_ERROR = 0, 1  # apps/exit_codes.hpp
QUICK_SHARED_MAPS = ("sur-2.h5", "KautschukInfiniteFocus.h5")
QUICK_TEST_MAPS = ("di-5-crop-48x64.h5", "kautschuk-crop-40x56.x3p")


@dataclass
class Run:
    map_name: str
    boundary: str
    law: str
    load_label: str
    args: list
    output: str
    law_parameters: dict = field(default_factory=dict)
    outcome: str = ""
    iterations: str = ""
    seconds: float = 0.0
    contact: str = ""
    note: str = ""
    command: list = field(default_factory=list)  # the command line, once run


SHARED = os.environ.get("SHARED", os.path.join(os.path.dirname(ROOT), "shared"))


def shared_directory():
    return SHARED


def default_maps(quick):
    topography = os.path.join(shared_directory(), "data", "topography")
    if quick:
        shared = [os.path.join(topography, name) for name in QUICK_SHARED_MAPS]
        if all(os.path.isfile(path) for path in shared):
            return shared
        return [os.path.join(ROOT, "tests", "data", name) for name in QUICK_TEST_MAPS]
    if not os.path.isdir(topography):
        return []
    maps = []
    for name in sorted(os.listdir(topography)):
        path = os.path.join(topography, name)
        if name.endswith(".h5"):
            with h5py.File(path, "r") as f:
                if f["height"].ndim == 2:
                    maps.append(path)
    return maps


def window_option(path, side):
    """The central side x side window of an HDF5 map (the whole map along an
    axis shorter than side); other formats whole."""
    if not path.endswith(".h5"):
        return []
    with h5py.File(path, "r") as f:
        ny, nx = f["height"].shape
    wx, wy = min(side, nx), min(side, ny)
    return ["--window", f"{(nx - wx) // 2},{(ny - wy) // 2},{wx},{wy}"]


class Runner:
    def __init__(self, program, work, threads, timeout, reuse=False, no_new_runs=False):
        self.program, self.work, self.threads, self.timeout = program, work, threads, timeout
        self.reuse, self.no_new_runs = reuse, no_new_runs
        self.environment = dict(os.environ, HALFSPACE_FFTW_WISDOM="off", OMP_NUM_THREADS=str(threads))

    def execute(self, run):
        """Runs one solve and classifies it (run.outcome and the rest). With
        reuse, a result file already in the work directory (of an earlier,
        interrupted matrix) is classified instead, its seconds the solve's
        own; with no_new_runs a missing one is `not run`."""
        command = [self.program, "solve", *run.args, "--threads", str(self.threads), "--quiet", "--output",
                   run.output]
        run.command = command
        if self.reuse and os.path.exists(run.output):
            with h5py.File(run.output, "r") as f:
                returncode = EXIT_OK if int(f.attrs["converged"]) == 1 else 2
                run.seconds = float(f.attrs["solve_seconds"])
            stderr, written = "", True
        elif self.no_new_runs:
            run.outcome = "not run"
            return run
        else:
            if os.path.exists(run.output):
                os.remove(run.output)
            start = time.perf_counter()
            try:
                process = subprocess.run(command, capture_output=True, text=True, timeout=self.timeout,
                                         env=self.environment)
            except subprocess.TimeoutExpired:
                run.seconds = time.perf_counter() - start
                run.outcome, run.note = "FAILED", f"no answer within {self.timeout:g} s"
                return run
            run.seconds = time.perf_counter() - start
            returncode, stderr = process.returncode, " ".join(process.stderr.split())
            written = os.path.exists(run.output)
        if returncode == EXIT_INPUT_ERROR:
            if written or not stderr:
                run.outcome = "FAILED"
                run.note = "exit 1 " + ("after writing a result" if written else "without a message")
            else:
                run.outcome, run.note = "refused", stderr.removeprefix("error: ")
            return run
        if not written:
            run.outcome, run.note = "FAILED", f"exit {returncode}, no result: {stderr}"
            return run
        with h5py.File(run.output, "r") as f:
            run.iterations = str(int(f.attrs["iterations"]))
            run.contact = f"{f.attrs['contact_fraction']:.3f}"
            if "plastic_fraction" in f.attrs and f.attrs["hardness"] > 0:
                run.contact += f" ({f.attrs['plastic_fraction']:.3f} plastic)"
            converged = int(f.attrs["converged"]) == 1
            message = str(f.attrs["message"])
        if returncode != EXIT_OK or not converged:
            run.outcome = "FAILED"
            run.note = f"exit {returncode}: {message or stderr}"
            return run
        problems = check_result(run.output, run)
        run.outcome = "FAILED" if problems else "converged"
        run.note = "; ".join(problems)
        return run


def law_traction(law, gap, parameters):
    """The cohesive traction t(gap) (Pa, negative: attraction) off the wall."""
    if law.startswith("md"):
        return np.where(gap < parameters["range"], -parameters["stress"], 0.0)
    return -parameters["stress"] * np.exp(-gap / parameters["range"])


def check_result(path, run):
    """What is wrong with a converged result, judged from its fields alone
    (the checks of the module docstring); an empty list if nothing."""
    problems = []
    with h5py.File(path, "r") as f:
        a = f.attrs
        fields = {name: f[name][...] for name in ("height", "pressure", "gap", "displacement") if name in f}
        plastic = f["plastic"][...].astype(bool) if "plastic" in f else None
        cell_area = a["dx"] * (a["dy"] if a["dimension"] == 2 else 1.0)
        for name, values in fields.items():
            if not np.all(np.isfinite(values)):
                problems.append(f"{name}: {np.count_nonzero(~np.isfinite(values))} values not finite")
        if problems:
            return problems
        p, gap, u, h = fields["pressure"], fields["gap"], fields["displacement"], fields["height"]
        approach, total_force = float(a["approach"]), float(a["total_force"])
        # The gap scale of the Polonsky-Keer residual: a coated body on a soft
        # substrate sinks by far more than the roughness (opd-1, free, 20 %:
        # ptp(u) = 1.4 um against an rms height of 7 nm), and the gaps are
        # differences of displacements that large.
        gap_scale = float(np.ptp(h) + np.ptp(u))
        p_ref = float(np.max(np.abs(p)))
        # The gap's definition: max(h) - h + u - approach, in one constant.
        offset = gap - u + approach + h
        scale = max(np.max(np.abs(gap)), np.max(np.abs(u)), abs(approach), np.max(np.abs(h)))
        if np.ptp(offset) > 1e-8 * scale:
            problems.append(f"gap - displacement + approach + height varies by {np.ptp(offset):.2e} m")
        # Force balance and the prescribed load.
        force = float(np.sum(p) * cell_area)
        if abs(force - total_force) > 1e-9 * np.sum(np.abs(p)) * cell_area:
            problems.append(f"sum p dA = {force:.9e} N against total_force {total_force:.9e} N")
        load_mode = str(a["load_mode"])
        target = run.law_parameters.get("target")
        adhesive = run.law.startswith(("md", "exp"))
        if load_mode == "mean_pressure" and target is not None:
            area = p.size * cell_area
            if adhesive:
                # The adhesive search's stated force tolerance (1e-6 of the
                # largest of the target, adhesive and repulsive forces, or
                # the inner solve's 1e-6 of p_ref over the active cells),
                # ten times.
                active = np.count_nonzero((gap <= 1e-6 * (np.ptp(h) + np.ptp(u))) | (p < 0)) * cell_area
                scale = max(abs(target) * area, -np.sum(np.minimum(p, 0)) * cell_area,
                            np.sum(np.maximum(p, 0)) * cell_area)
                allowed = 10 * max(1e-6 * scale, 1e-6 * p_ref * active)
            else:
                allowed = 1e-9 * np.sum(np.abs(p)) * cell_area
            if abs(float(a["mean_pressure"]) - target) * area > allowed:
                problems.append(f"mean pressure {float(a['mean_pressure']):.6e} Pa against {target:.6e} Pa asked "
                                f"(force off by {abs(float(a['mean_pressure']) - target) * area:.2e} N, "
                                f"{allowed:.2e} N allowed)")
        if load_mode == "approach" and target is not None and abs(approach - target) > 1e-12 * abs(target):
            problems.append(f"approach {approach:.6e} m against {target:.6e} m asked")
        # Bounds, complementarity and the law.
        law, parameters = run.law, run.law_parameters
        hardness = float(a["hardness"])
        lower = -parameters["stress"] if adhesive else 0.0
        # Polonsky-Keer projects onto its bounds exactly; the adhesive solver
        # reports a cell on the wall at its pressure S v, right to its
        # residual, 1e-6 of the largest |p| (adhesive_contact_solver.hpp):
        # ten times that.
        if np.min(p) < lower - (1e-5 if adhesive else 1e-9) * p_ref:
            problems.append(f"pressure {np.min(p):.4e} Pa below its bound {lower:.4e} Pa")
        if hardness > 0 and np.max(p) > hardness * (1 + 1e-9):
            problems.append(f"pressure {np.max(p):.6e} Pa above the hardness {hardness:.6e} Pa")
        gap_tolerance = 1e-6 * gap_scale
        at_cap = (p >= hardness * (1 - 1e-9)) if hardness > 0 else np.zeros(p.shape, bool)
        elastic_cells = ~at_cap
        if np.any(gap[elastic_cells] < -gap_tolerance):
            problems.append(f"penetration: least gap {np.min(gap[elastic_cells]):.3e} m off the cap")
        if hardness > 0:
            if np.any(gap[at_cap] > gap_tolerance):
                problems.append(f"{np.count_nonzero(gap[at_cap] > gap_tolerance)} cells at the cap are off the wall")
            if plastic is not None and np.count_nonzero(plastic != at_cap) > 0:
                problems.append(f"/plastic differs from p = H at {np.count_nonzero(plastic != at_cap)} cells")
        repulsive = np.maximum(p, 0.0) * elastic_cells
        if np.sum(repulsive) > 0:
            complementarity = np.sum(repulsive * np.abs(gap)) / (np.sum(repulsive) * gap_scale)
            if complementarity > 1e-6:
                problems.append(f"complementarity sum p|gap| / (sum p g_ref) = {complementarity:.2e}")
        if adhesive:
            off_wall = gap > gap_tolerance
            error = np.abs(p - law_traction(law, gap, parameters))
            if law.startswith("md"):
                error[np.abs(gap - parameters["range"]) <= gap_tolerance] = 0.0
            if np.any(off_wall) and np.max(error[off_wall]) > 1e-4 * p_ref:
                problems.append(f"traction off the wall differs from the law by {np.max(error[off_wall]):.3e} Pa "
                                f"(largest |p| {p_ref:.3e} Pa)")
    return problems


def calibrate(runner, name, map_args, boundary, window_cells, targets):
    """The elastic runs at about the target contact areas (1, 5 and 20 %): a
    secant on log p against log area from the rough-surface estimate."""
    runs = []
    slope = None
    for target in targets:
        pressure = None
        history = []
        output = os.path.join(runner.work, f"{name}-{boundary}-elastic-{target}.h5")
        reused = runner.reuse and os.path.exists(output)
        if reused:
            with h5py.File(output, "r") as f:
                pressure = float(f.attrs["mean_pressure"])
        for attempt in range(6):
            if pressure is None:
                pressure = 0.5 * target * E_STAR * (slope or 0.1)
            run = Run(name, boundary, "elastic", f"{target:.0%}", [*map_args, "--boundary", boundary, "--E-star",
                      f"{E_STAR:g}", "--mean-pressure", f"{pressure:.6g}"],
                      os.path.join(runner.work, f"{name}-{boundary}-elastic-{target}.h5"),
                      {"target": float(f"{pressure:.6g}"), "stress": 0.0})
            runner.execute(run)
            if not os.path.exists(run.output):
                break
            # A result that did not converge still gives the laws their load.
            with h5py.File(run.output, "r") as f:
                area = float(f.attrs["contact_fraction"])
                slope = slope or float(f.attrs["surface_rms_slope"])
                run.law_parameters["approach"] = float(f.attrs["approach"])
            if run.outcome != "converged" or reused:
                break
            history.append((math.log(pressure), math.log(max(area, 1.0 / window_cells))))
            if abs(math.log(max(area, 1e-12) / target)) < math.log(1.25):
                break
            exponent = 1.0
            if len(history) >= 2 and history[-1][1] != history[-2][1]:
                exponent = (history[-1][1] - history[-2][1]) / (history[-1][0] - history[-2][0])
                exponent = min(max(exponent, 0.3), 3.0)
            pressure = math.exp(history[-1][0] + (math.log(target) - history[-1][1]) / exponent)
        runs.append(run)
    return runs


def matrix_runs(work, name, map_args, boundary, elastic, dx):
    """The law runs of one map and boundary, at the loads of its elastic runs."""
    middle = elastic[len(elastic) // 2]
    if not all(os.path.exists(run.output) and "approach" in run.law_parameters for run in elastic):
        return []
    with h5py.File(middle.output, "r") as f:
        contact_pressure = float(f.attrs["mean_pressure"]) / max(float(f.attrs["contact_fraction"]), 1e-12)
    # As the program reads them (six digits), so that the checks use its law.
    h0 = float(f"{4.0 * dx * 0.5 * contact_pressure / E_STAR:.6g}")
    w = float(f"{0.5 * contact_pressure * h0:.6g}")
    layer_e = E_STAR * (1 - NU**2)
    base = [*map_args, "--boundary", boundary]
    material = ["--E-star", f"{E_STAR:g}"]
    laws = {
        "hardness-high": (material + ["--hardness", f"{4 * contact_pressure:.6g}"], {}),
        "hardness-low": (material + ["--hardness", f"{contact_pressure:.6g}"], {}),
        "md-force": (material + ["--adhesion", "md", "--work-of-adhesion", f"{w:.6g}", "--adhesion-range",
                                 f"{h0:.6g}"], {"range": h0, "stress": w / h0}),
        "exp-force": (material + ["--adhesion", "exponential", "--work-of-adhesion", f"{w:.6g}",
                                  "--adhesion-range", f"{h0:.6g}"], {"range": h0, "stress": w / h0}),
        "coat-soft": (["--layer-thickness", f"{10 * dx:.6g}", "--layer-E", f"{layer_e:.6g}", "--layer-nu", f"{NU}",
                       "--substrate-E", f"{layer_e / 0.1:.6g}", "--substrate-nu", f"{NU}"], {}),
        "coat-hard": (["--layer-thickness", f"{10 * dx:.6g}", "--layer-E", f"{layer_e:.6g}", "--layer-nu", f"{NU}",
                       "--substrate-E", f"{layer_e / 1e3:.6g}", "--substrate-nu", f"{NU}"], {}),
    }
    laws["md-approach"] = laws["md-force"]
    laws["exp-approach"] = laws["exp-force"]
    runs = []
    loads = elastic
    for law in LAWS[1:]:
        options, parameters = laws[law]
        for load in loads:
            if law.endswith("approach"):
                value = float(f"{load.law_parameters['approach']:.9g}")
                load_args = [f"--approach={value:.9g}"]
            else:
                value = load.law_parameters["target"]
                load_args = ["--mean-pressure", f"{value:.6g}"]
            runs.append(Run(name, boundary, law, load.load_label, base + options + load_args,
                            os.path.join(work, f"{name}-{boundary}-{law}-{load.load_label}.h5".replace("%", "")),
                            {**parameters, "target": value, "stress": parameters.get("stress", 0.0)}))
    return runs


def markdown(runs, title):
    outcomes = ["converged", "refused", "FAILED"] + (["not run"] if any(r.outcome == "not run" for r in runs) else [])
    lines = [f"### {title}", "", "| law | " + " | ".join(outcomes) + " |", "|---" * (len(outcomes) + 1) + "|"]
    for law in LAWS:
        mine = [run for run in runs if run.law == law]
        if mine:
            counts = [sum(run.outcome == outcome for run in mine) for outcome in outcomes]
            lines.append(f"| {law} | " + " | ".join(map(str, counts)) + " |")
    lines += ["", "| map | boundary | law | load | outcome | iterations | seconds | contact fraction | note |",
              "|---|---|---|---|---|---|---|---|---|"]
    for run in runs:
        note = run.note.replace("|", "\\|")
        if len(note) > 240:
            note = note[:237] + "..."
        lines.append(f"| {run.map_name} | {run.boundary} | {run.law} | {run.load_label} | {run.outcome} | "
                     f"{run.iterations} | {run.seconds:.2f} | {run.contact} | {note} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("maps", nargs="*", help="height maps [the 2D maps of ../shared/data/topography]")
    parser.add_argument("--halfspace", default=os.path.join(ROOT, "build", "bin", "halfspace"))
    parser.add_argument("--window", type=int, help="window side in cells [256; 64 with --quick]")
    parser.add_argument("--boundaries", default="periodic,free")
    parser.add_argument("--laws", default=",".join(LAWS[1:]), help="comma-separated, of " + ", ".join(LAWS[1:]))
    parser.add_argument("--jobs", type=int, default=2, help="solves side by side [2]")
    parser.add_argument("--threads", type=int, default=1, help="threads per solve [1]")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds a solve may take [900]")
    parser.add_argument("--markdown", help="write the matrix as Markdown to this file")
    parser.add_argument("--work", help="keep the result files in this directory [a temporary one]")
    parser.add_argument("--reuse", action="store_true",
                        help="classify the result files already in --work instead of solving again (resuming)")
    parser.add_argument("--no-new-runs", action="store_true", help="with --reuse: mark the missing runs `not run`")
    parser.add_argument("--quick", action="store_true", help="two maps, 64 x 64, the middle load (the ctest)")
    parser.add_argument("--shared", help="the shared data folder [$SHARED, else ../shared beside the project root]")
    args = parser.parse_args()
    if args.shared:
        global SHARED
        SHARED = args.shared
    maps = [os.path.abspath(path) for path in args.maps] or default_maps(args.quick)
    missing = [path for path in maps if not os.path.isfile(path)]
    if not maps or missing:
        parser.error(f"no height maps: {', '.join(missing) or shared_directory() + '/data/topography is empty'}")
    side = args.window or (64 if args.quick else 256)
    boundaries = args.boundaries.split(",")
    laws = set(args.laws.split(","))
    unknown = laws - set(LAWS[1:])
    if unknown or any(b not in ("periodic", "free") for b in boundaries):
        parser.error(f"unknown law or boundary: {', '.join(sorted(unknown)) or args.boundaries}")
    with tempfile.TemporaryDirectory() as temporary:
        work = args.work or temporary
        os.makedirs(work, exist_ok=True)
        runner = Runner(os.path.abspath(args.halfspace), work, args.threads, args.timeout, args.reuse,
                        args.no_new_runs)
        cases = []
        for path in maps:
            name = os.path.splitext(os.path.basename(path))[0]
            window = window_option(path, side)
            map_args = ["--height-map", path, "--invalid", "fill", *window, "--detrend", "plane"]
            for boundary in boundaries:
                cases.append((name, map_args, boundary))
        targets = TARGET_AREAS[1:2] if args.quick else TARGET_AREAS
        start = time.perf_counter()
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            elastic = list(pool.map(lambda case: calibrate(runner, *case, side * side, targets), cases))
            runs = []
            for case, elastic_runs in zip(cases, elastic):
                runs += elastic_runs
                if os.path.exists(elastic_runs[0].output):
                    with h5py.File(elastic_runs[0].output, "r") as f:
                        dx = float(f.attrs["dx"])
                    runs += [run for run in matrix_runs(work, *case, elastic_runs, dx) if run.law in laws]
            for run in runs:
                if run.law == "elastic" and run.outcome == "FAILED":
                    print(f"FAILED {' '.join(run.command)}\n  {run.note}", flush=True)
            pending = [run for run in runs if run.law != "elastic"]
            for done, run in enumerate(pool.map(runner.execute, pending), 1):
                if run.outcome == "FAILED":
                    print(f"FAILED [{done}/{len(pending)}] {' '.join(run.command)}\n  {run.note}", flush=True)
        total = time.perf_counter() - start
    title = (f"Robustness matrix: {len(maps)} maps, {side} x {side} windows, {', '.join(boundaries)}; "
             f"{len(runs)} runs in {total:.0f} s ({args.jobs} jobs x {args.threads} thread)")
    table = markdown(runs, title)
    print(table)
    if args.markdown:
        with open(args.markdown, "w") as out:
            out.write(table)
    failed = sum(run.outcome == "FAILED" for run in runs)
    print(f"{failed} FAILED of {len(runs)}" if failed else f"all {len(runs)} runs converged or were refused")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
