"""read_height_map on every format the library reads, against the HDF5
crop they were all written from (tests/data/README.md), and the
preparation keywords."""

import numpy as np
import pytest

import halfspace as hs

DX = 1.953125e-9  # m, the di-5 AFM map's spacing


@pytest.fixture(scope="module")
def reference():
    from conftest import DATA
    return hs.read_height_map(DATA / "di-5-crop-48x64.h5")


def test_hdf5_reference(reference):
    assert reference.shape == (48, 64)
    assert reference.dx == pytest.approx(DX, rel=1e-12) and reference.dy == pytest.approx(DX, rel=1e-12)
    assert reference.preparation == ()


@pytest.mark.parametrize("name", ["di-5-crop-c-le-f8.npy", "di-5-crop-c-be-f8.npy", "di-5-crop-f-le-f8.npy",
                                  "di-5-crop-f-be-f8.npy", "di-5-crop-space.txt", "di-5-crop-comma.csv"])
def test_exact_formats_give_the_same_heights(data_dir, reference, name):
    surface = hs.read_height_map(data_dir / name, dx=DX, dy=DX)
    assert np.array_equal(surface.heights, reference.heights)


def test_float32_npy(data_dir, reference):
    surface = hs.read_height_map(data_dir / "di-5-crop-c-le-f4.npy", dx=DX, dy=DX)
    assert np.array_equal(surface.heights, reference.heights.astype(np.float32).astype(np.float64))


@pytest.mark.parametrize("name", ["di-5-crop-m.gsf", "di-5-crop-um-nm.gsf"])
def test_gsf(data_dir, reference, name):
    surface = hs.read_height_map(data_dir / name)
    # float32 storage: half an ulp of float32 relative to the largest height.
    scale = np.max(np.abs(reference.heights))
    assert np.max(np.abs(surface.heights - reference.heights)) <= 2 ** -23 * scale
    assert surface.dx == pytest.approx(DX, rel=1e-6)


def test_x3p_with_mask(data_dir):
    surface = hs.read_height_map(data_dir / "kautschuk-crop-40x56.x3p", invalid="fill")
    assert surface.shape[1] <= 56 and surface.shape[0] <= 40
    assert np.all(np.isfinite(surface.heights))
    assert any("fill" in line for line in surface.preparation)
    assert surface.dx == pytest.approx(2.279984215e-6, rel=1e-9)


def test_x3p_refuses_invalid_points_by_default(data_dir):
    with pytest.raises(hs.FileError, match="invalid='fill'"):
        hs.read_height_map(data_dir / "int16-mask-5x3.x3p")


def test_profiles(data_dir):
    profile = hs.read_height_map(data_dir / "dektak-1-crop-x-z.txt", format="profile")
    crop = hs.read_height_map(data_dir / "dektak-1-crop-256.h5")
    assert profile.shape == crop.shape == (256,) and profile.dy is None
    assert np.allclose(profile.heights, crop.heights, rtol=1e-12, atol=1e-18)
    dektak = hs.read_height_map(data_dir / "dektak-1.csv")
    assert dektak.dimension == 1 and dektak.shape == (9600,)
    assert np.array_equal(dektak.heights[:256], crop.heights)


def test_spacing_rules(data_dir):
    with pytest.raises(hs.FileError, match="dx and dy"):
        hs.read_height_map(data_dir / "di-5-crop-c-le-f8.npy")
    with pytest.raises(hs.InputError, match="dx=-1"):
        hs.read_height_map(data_dir / "di-5-crop-c-le-f8.npy", dx=-1.0, dy=1.0)
    surface = hs.read_height_map(data_dir / "di-5-crop-c-le-f8.npy", dx=2e-9, dy=3e-9, unit="nm")
    assert surface.dx == 2e-9 and surface.dy == 3e-9


def test_unit_scales_heights(data_dir, reference):
    in_nm = hs.read_height_map(data_dir / "di-5-crop-c-le-f8.npy", unit="nm", dx=DX, dy=DX)
    assert np.allclose(in_nm.heights, reference.heights * 1e-9, rtol=1e-15, atol=0)


def test_window_and_detrend(data_dir, reference):
    window = hs.read_height_map(data_dir / "di-5-crop-48x64.h5", window=(4, 8, 32, 16), detrend="plane")
    assert window.shape == (16, 32)
    assert len(window.preparation) == 2
    # The plane fit removes the mean and both tilts: the residual is orthogonal to 1, x and y.
    j, i = np.mgrid[0:16, 0:32]
    for basis in (np.ones_like(i), i, j):
        assert abs(np.sum(window.heights * basis)) < 1e-12 * np.sum(np.abs(window.heights)) * basis.max()
    same = reference.prepare(window="4,8,32,16", detrend="plane")
    assert np.array_equal(same.heights, window.heights)


def test_resample_keeps_lengths_and_planes(data_dir, reference):
    # A plane on the cell centres stays that plane on the new centres.
    ny, nx, dx = 12, 16, 1e-6
    y, x = (np.mgrid[0:ny, 0:nx] + 0.5) * dx
    plane = _plane(x, y)
    for cells in ((40, 30), "8x6", (40, 6)):
        resampled = hs.HeightMap(plane, dx).prepare(resample=cells)
        new_ny, new_nx = resampled.shape
        assert resampled.size == pytest.approx((nx * dx, ny * dx), rel=1e-14)
        y2, x2 = (np.mgrid[0:new_ny, 0:new_nx] + 0.5)
        expected = _plane(x2 * resampled.dx, y2 * resampled.dy)
        assert np.max(np.abs(resampled.heights - expected)) < 1e-18
        assert "resample" in resampled.preparation[-1]
    read = hs.read_height_map(data_dir / "di-5-crop-48x64.h5", detrend="plane", resample=(128, 96))
    assert read.shape == (96, 128) and read.dx == pytest.approx(DX / 2, rel=1e-14)
    profile = hs.HeightMap(np.arange(10.0) * 1e-9, 1e-6).prepare(resample=20)
    assert profile.shape == (20,)
    with pytest.raises(hs.InputError, match="more than 16 times"):
        reference.prepare(resample=(2000, 48))
    with pytest.raises(hs.InputError, match="expected NXxNY"):
        reference.prepare(resample="64by48")


def _plane(x, y):
    return 1e-7 + 0.01 * x - 0.02 * y


def test_array_heights_with_nan_prepare():
    heights = np.add.outer(np.arange(8.0), np.arange(10.0)) * 1e-9
    heights[3, 4] = np.nan
    surface = hs.HeightMap(heights, 1e-6)
    with pytest.raises(hs.FileError, match="invalid"):
        surface.prepare()
    filled = surface.prepare(invalid="fill")
    # The harmonic fill reproduces a plane exactly (to rounding).
    assert filled.heights[3, 4] == pytest.approx(7e-9, rel=1e-10)
