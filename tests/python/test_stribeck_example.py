"""The Stribeck examples on the measured Dektak profile
(examples/python/stribeck_measured.py and examples/stribeck_measured.sh): they
run, the curve goes from full film to boundary lubrication, and the Python
curve is the program's (its CSV printed to 9 digits)."""

import csv
import importlib.util
import os
import pathlib
import subprocess
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
PYTHON_EXAMPLE = ROOT / "examples" / "python" / "stribeck_measured.py"
SHELL_EXAMPLE = ROOT / "examples" / "stribeck_measured.sh"


def _read(path):
    with open(path, newline="") as file:
        return list(csv.DictReader(file))


def test_stribeck_examples_agree(tmp_path, cli):
    python = subprocess.run([sys.executable, str(PYTHON_EXAMPLE), str(tmp_path / "py"), "--quick"],
                            capture_output=True, text=True, timeout=600)
    assert python.returncode == 0, python.stderr
    shell = subprocess.run(["bash", str(SHELL_EXAMPLE), str(tmp_path / "sh")], capture_output=True, text=True,
                           timeout=600, env={**os.environ, "HALFSPACE": cli, "QUICK": "1", "NO_PLOT": "1"})
    assert shell.returncode == 0, shell.stderr
    mine, program = _read(tmp_path / "py" / "stribeck.csv"), _read(tmp_path / "sh" / "stribeck.csv")
    assert len(mine) == len(program) == 5
    for name in ("entrainment_speed", "hersey_number", "friction_coefficient", "contact_load_fraction",
                 "central_film_thickness", "minimum_film_thickness"):
        np.testing.assert_allclose([float(row[name]) for row in mine], [float(row[name]) for row in program],
                                   rtol=1e-8, atol=1e-300, err_msg=name)
    assert all(row["status"] == "converged" for row in mine)
    share = [float(row["contact_load_fraction"]) for row in mine]
    mu = [float(row["friction_coefficient"]) for row in mine]
    # Full film at the fastest speed, mixed in between, nearly all contact at the slowest,
    # where mu tends to the Coulomb coefficient of the contacts (0.1).
    assert share[0] == 0.0 and 0.05 < share[3] < 0.95 and share[-1] > 0.95
    assert 0.09 < mu[-1] <= 0.1 and mu[0] < 0.5 * mu[-1]
    if importlib.util.find_spec("matplotlib") is not None:
        for figure in ("stribeck.png", "transition.png"):
            assert (tmp_path / "py" / figure).stat().st_size > 5000, figure
