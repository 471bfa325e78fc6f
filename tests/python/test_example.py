"""examples/python/rough_contact.py runs and writes its files."""

import importlib.util
import pathlib
import subprocess
import sys

import halfspace as hs

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "rough_contact.py"


def test_rough_contact_example(tmp_path):
    run = subprocess.run([sys.executable, str(EXAMPLE), str(tmp_path), "--steps", "4"], capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    table = hs.read_result(tmp_path / "sweep.h5")
    assert table.converged
    assert (tmp_path / "sweep.csv").is_file()
    if importlib.util.find_spec("matplotlib") is not None:
        for figure in ("contact_area.png", "pressure.png"):
            assert (tmp_path / figure).stat().st_size > 1000, figure
    else:
        assert "matplotlib is not installed" in run.stdout
