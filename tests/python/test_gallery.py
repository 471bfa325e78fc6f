"""The gallery's ParaView example (docs/gallery.md#opening-a-result-in-paraview):
examples/gallery/von_mises.sh on a small grid, then paraview_screenshot.py
draws its XDMF sidecar offscreen with the vtk wheel. The other examples run
as ctest tests (examples/CMakeLists.txt)."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("h5py", reason="h5py is not installed (scripts/test-python.sh installs it)")
pytest.importorskip("vtkmodules.vtkIOXdmf2",
                    reason="the vtk wheel is not installed (no wheel for this platform or Python?)")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

GALLERY = pathlib.Path(__file__).resolve().parents[2] / "examples" / "gallery"


def test_paraview_screenshot_from_the_sidecar(tmp_path, cli):
    env = dict(os.environ, QUICK="1", HALFSPACE=cli, PYTHON=sys.executable, HALFSPACE_FFTW_WISDOM="off")
    subprocess.run(["bash", str(GALLERY / "von_mises.sh"), str(tmp_path)], check=True, env=env)
    assert (tmp_path / "von_mises.png").stat().st_size > 0
    png = tmp_path / "paraview.png"
    subprocess.run([sys.executable, str(GALLERY / "paraview_screenshot.py"), str(tmp_path / "hertz_stress.xdmf"),
                    "--out", str(png)], check=True, env=env)
    reader = vtkPNGReader()
    reader.SetFileName(str(png))
    reader.Update()
    image = reader.GetOutput()
    assert image.GetDimensions()[:2] == (640, 420)
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    # Something was drawn: the white background, the low end (blue) and the
    # high end (red) of both colour maps, the contact and the stress peak.
    white = (pixels == 255).all(axis=1).mean()
    red = ((pixels[:, 0] > 200) & (pixels[:, 1] < 80) & (pixels[:, 2] < 80)).sum()
    blue = ((pixels[:, 2] > 120) & (pixels[:, 0] < 60)).sum()
    assert 0.2 < white < 0.95
    assert red > 200 and blue > 2000
    assert np.unique(pixels, axis=0).shape[0] > 20
