"""Errors reach Python as InputError (a ValueError) and FileError (an
OSError) with the library's message, naming the keyword and the value."""

import numpy as np
import pytest

import halfspace as hs

SPHERE = hs.generate.sphere(grid=(16, 16), size=1e-3, radius=0.01)


def test_exception_types():
    assert issubclass(hs.InputError, ValueError)
    assert issubclass(hs.FileError, OSError)
    assert not issubclass(hs.FileError, ValueError)


@pytest.mark.parametrize("keywords, message", [
    ({"tol": 2.0}, "tol=2 is invalid"),
    ({"tol": 0.0}, "tol=0 is invalid"),
    ({"max_iter": 0}, "max_iter=0"),
    ({"solver": "cg"}, "solver=cg"),
    ({"boundary": "open"}, "open"),
    ({"fft_planning": "fast"}, "fft_planning"),
    ({"threads": 0}, "threads=0 is invalid"),
    ({"deflation_block": -1}, "deflation_block=-1"),
    ({"precision": "half"}, "precision=half is invalid"),
    ({"precision": "mixed", "solver": "lemke"}, "precision=mixed does not apply to solver 'lemke'"),
])
def test_bad_option_names_keyword(keywords, message):
    with pytest.raises(hs.InputError, match=message):
        hs.solve(SPHERE, e_star=1e9, force=0.1, **keywords)


def test_load_and_material_rules():
    with pytest.raises(hs.InputError, match="no load given"):
        hs.solve(SPHERE, e_star=1e9)
    with pytest.raises(hs.InputError, match="force and approach cannot be combined"):
        hs.solve(SPHERE, e_star=1e9, force=1.0, approach=1e-6)
    with pytest.raises(hs.InputError, match="force"):
        hs.solve(SPHERE, e_star=1e9, force=-1.0)
    with pytest.raises(hs.InputError, match="no material given"):
        hs.solve(SPHERE, force=1.0)
    with pytest.raises(hs.InputError, match="missing nu2"):
        hs.solve(SPHERE, E1=1e9, nu1=0.3, E2=1e9, force=1.0)
    with pytest.raises(hs.InputError, match="e_star cannot be combined with E1"):
        hs.solve(SPHERE, e_star=1e9, E1=1e9, force=1.0)
    with pytest.raises(ValueError):  # catchable as the built-in type too
        hs.solve(SPHERE, e_star=-1.0, force=1.0)


def test_array_surface_needs_spacing_and_finite_heights():
    with pytest.raises(hs.InputError, match="dx="):
        hs.solve(np.zeros((8, 8)), e_star=1e9, force=1.0)
    heights = np.zeros((8, 8))
    heights[3, 3] = np.nan
    with pytest.raises(hs.InputError, match="non-finite height"):
        hs.solve(heights, dx=1e-6, e_star=1e9, force=1.0)
    with pytest.raises(hs.InputError, match="initial_pressure has 4 values"):
        hs.solve(SPHERE, e_star=1e9, force=0.1, initial_pressure=np.ones(4))


def test_file_errors(tmp_path, data_dir):
    with pytest.raises(hs.FileError, match="no-such-file.h5"):
        hs.read_height_map(tmp_path / "no-such-file.h5")
    with pytest.raises(OSError):
        hs.read_result(tmp_path / "missing.h5")
    with pytest.raises(hs.FileError, match="not a halfspace result"):
        hs.read_result(data_dir / "di-5-crop-48x64.h5")
    result = hs.solve(SPHERE, e_star=1e9, force=0.1, fft_planning="estimate", threads=1)
    with pytest.raises(hs.FileError):
        result.save(tmp_path / "no-such-directory" / "out.h5")


def test_reader_option_errors(data_dir):
    with pytest.raises(hs.InputError, match="detrend"):
        hs.read_height_map(data_dir / "di-5-crop-48x64.h5", detrend="cubic")
    with pytest.raises(hs.InputError, match="invalid"):
        hs.read_height_map(data_dir / "di-5-crop-48x64.h5", invalid="ignore")
    with pytest.raises(hs.InputError, match="format"):
        hs.read_height_map(data_dir / "di-5-crop-48x64.h5", format="tiff")
