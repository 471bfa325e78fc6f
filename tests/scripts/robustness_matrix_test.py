#!/usr/bin/python3
"""The quick robustness matrix (bench/robustness_matrix.py --quick: two
measured maps at 64 x 64, every interface law, periodic and free, the 5 %
load), and its result checks shown to catch what they are for: a result
corrupted in each way must be flagged.

  robustness_matrix_test.py HALFSPACE_EXECUTABLE SOURCE_DIR WORK_DIR

The maps come from ../shared beside the project root ($SHARED), or without it
from the crops in tests/data, so the test never skips.
"""

import importlib.util
import pathlib
import shutil
import subprocess
import sys

import h5py
import numpy as np

executable, source, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
script = source / "bench" / "robustness_matrix.py"
spec = importlib.util.spec_from_file_location("robustness_matrix", script)
matrix = importlib.util.module_from_spec(spec)
spec.loader.exec_module(matrix)

failures = []
completed = subprocess.run([sys.executable, str(script), "--quick", "--halfspace", executable, "--work",
                            str(work / "runs"), "--markdown", str(work / "matrix.md")], text=True,
                           capture_output=True)
print(completed.stdout, completed.stderr)
if completed.returncode != 0:
    failures.append(f"the quick matrix exited {completed.returncode}")
table = (work / "matrix.md").read_text() if (work / "matrix.md").exists() else ""
for law in matrix.LAWS:
    if f"| {law} | " not in table:
        failures.append(f"the matrix has no row for {law}")

# The checks against corrupted copies of converged results: an adhesive one
# (signed pressure, a law off the wall) and a capped one.
runs = work / "runs"
for law, parameters in (("md-approach", None), ("hardness-low", {})):
    original = sorted(runs.glob(f"*-periodic-{law}-5.h5"))[0]
    with h5py.File(original, "r") as f:
        if parameters is None:
            stress = float(f.attrs["adhesion_stress"])
            parameters = {"range": float(f.attrs["adhesion_range"]), "stress": stress}
        parameters = {**parameters, "stress": parameters.get("stress", 0.0)}
        approach = float(f.attrs["approach"])
        hardness = float(f.attrs["hardness"])
    run = matrix.Run("map", "periodic", law, "5%", [], str(original),
                     {**parameters, "target": approach if law.endswith("approach") else None})
    untouched = matrix.check_result(str(original), run)
    if untouched:
        failures.append(f"{law}: the solver's own result fails the checks: {untouched}")

    def corrupted(description, expected, change):
        """A copy of the result changed by `change` must fail the check
        whose message contains `expected`."""
        copy = work / f"corrupted-{law}.h5"
        shutil.copy(original, copy)
        with h5py.File(copy, "r+") as f:
            change(f)
        problems = matrix.check_result(str(copy), run)
        if not any(expected in problem for problem in problems):
            failures.append(f"{law}: a result with {description} is not caught as '{expected}': {problems}")

    def set_pressure(index_of, value):
        """One cell's pressure, with total_force kept in balance."""
        def change(f):
            p = f["pressure"][...]
            cell = index_of(f)
            p[cell] = value(p[cell], f)
            f["pressure"][...] = p
            if np.all(np.isfinite(p)):
                f.attrs.modify("total_force", np.sum(p) * f.attrs["dx"] * f.attrs["dy"])
        return change

    def set_gap(index_of, value, displacement_too):
        """One cell's gap; with displacement_too its displacement moves
        alike, so that the gap's definition still holds."""
        def change(f):
            gap, u = f["gap"][...], f["displacement"][...]
            cell = index_of(f)
            new = value(gap[cell], f)
            if displacement_too:
                u[cell] += new - gap[cell]
            gap[cell] = new
            f["gap"][...], f["displacement"][...] = gap, u
        return change

    contact_cell = lambda f: np.unravel_index(np.argmax(f["pressure"][...]), f["pressure"].shape)
    open_cell = lambda f: np.unravel_index(np.argmax(f["gap"][...]), f["gap"].shape)
    rms = lambda f: np.std(f["height"][...])
    corrupted("a NaN pressure", "not finite", set_pressure(contact_cell, lambda v, f: np.nan))
    corrupted("total_force off by 1e-6", "total_force",
              lambda f: f.attrs.modify("total_force", f.attrs["total_force"] * (1 + 1e-6)))
    corrupted("a gap unlike its definition", "gap - displacement",
              set_gap(open_cell, lambda v, f: v * 1.001, False))
    corrupted("a penetration", "penetration",
              set_gap(contact_cell if law != "hardness-low" else open_cell, lambda v, f: -1e-3 * rms(f), True))
    if law == "hardness-low":
        corrupted("a pressure above the hardness", "above the hardness",
                  set_pressure(contact_cell, lambda v, f: 1.01 * hardness))
        corrupted("a tension", "below its bound", set_pressure(open_cell, lambda v, f: -1e-3 * hardness))
        corrupted("a pressure where the gap is open", "complementarity",
                  set_pressure(open_cell, lambda v, f: 0.1 * hardness))
        corrupted("a plastic cell off the wall", "off the wall",
                  set_gap(contact_cell, lambda v, f: 1e-3 * rms(f), True))
    else:
        corrupted("a traction off the law", "traction off the wall",
                  set_pressure(open_cell, lambda v, f: -0.5 * parameters["stress"]))
        corrupted("a tension beyond the law's", "below its bound",
                  set_pressure(contact_cell, lambda v, f: -1.01 * parameters["stress"]))

for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
