"""Instrument formats halfspace does not read go to SurfaceTopography: a
clear message when it is absent (always tested), and, where it is
installed, the originals in ../shared/data/topography against their HDF5
conversions there (the README there: height == Topography.heights().T)."""

import importlib.util
import pathlib
import sys

import numpy as np
import pytest

import halfspace as hs

HAVE_SURFACE_TOPOGRAPHY = importlib.util.find_spec("SurfaceTopography") is not None


def test_absent_package_is_named(monkeypatch, tmp_path):
    # None in sys.modules makes `import SurfaceTopography` fail, installed or
    # not. The files only need their extension (and, for .dat, binary bytes):
    # the choice of reader is made before anything is parsed, so the test
    # needs no instrument file and runs wherever the package does.
    monkeypatch.setitem(sys.modules, "SurfaceTopography", None)
    for name in ("scan.sur", "scan.plu", "scan.opd", "scan.di"):
        (tmp_path / name).write_bytes(b"\x00\x01instrument data\xff")
        with pytest.raises(hs.FileError, match=r"install the SurfaceTopography package") as error:
            hs.read_height_map(tmp_path / name)
        assert name in str(error.value)
        assert f"'.{name.split('.')[-1]}'" in str(error.value)
    # A binary .dat (Zygo MetroPro) is not a text matrix: the message names the package too.
    (tmp_path / "metropro.dat").write_bytes(b"\x88\x1b\x03\x6f" + bytes(range(256)) * 8)
    with pytest.raises(hs.FileError, match="SurfaceTopography"):
        hs.read_height_map(tmp_path / "metropro.dat")
    converted = pathlib.Path(__file__).resolve().parents[1] / "data" / "di-5-crop-48x64.h5"
    with pytest.raises(hs.FileError, match="format='surfacetopography' was asked"):
        hs.read_height_map(converted, format="surfacetopography")


@pytest.mark.skipif(not HAVE_SURFACE_TOPOGRAPHY, reason="SurfaceTopography is not installed (optional)")
@pytest.mark.parametrize("original, converted", [("di-5.di", "di-5.h5"), ("sur-2.sur", "sur-2.h5"),
                                                 ("plu-1.plu", "plu-1.h5"), ("metropro-1.dat", "metropro-1.h5"),
                                                 ("opd-1.opd", "opd-1.h5")])
def test_originals_match_their_conversions(shared_topography, original, converted):
    import SurfaceTopography

    surface = hs.read_height_map(shared_topography / original, invalid="fill")
    reference = hs.read_height_map(shared_topography / converted, invalid="fill")
    assert surface.shape == reference.shape
    assert surface.dx == pytest.approx(reference.dx, rel=1e-6)
    assert surface.dy == pytest.approx(reference.dy, rel=1e-6)
    # Compare where SurfaceTopography saw data: its mask, transposed to (ny, nx),
    # marks the points both sides filled (each in its own way) or, for
    # sur-2, kept as the file's raw invalid value.
    heights = SurfaceTopography.open_topography(str(shared_topography / original)).topography().heights()
    measured = ~np.ma.getmaskarray(heights).T
    assert measured.mean() > 0.99
    # Both decode the same integers or floats with the same scale: equal to float32 rounding of the range.
    scale = np.ptp(reference.heights[measured])
    assert np.max(np.abs(surface.heights - reference.heights)[measured]) <= 1e-6 * scale
