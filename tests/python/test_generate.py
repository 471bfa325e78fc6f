"""The generators match `halfspace generate`'s definitions."""

import numpy as np
import pytest

import halfspace as hs


def test_sphere_heights():
    surface = hs.generate.sphere(grid=(8, 6), size=(8e-3, 6e-3), radius=0.1)
    assert surface.shape == (6, 8) and surface.dx == 1e-3 and surface.dy == 1e-3
    x = (np.arange(8) - 3.5) * 1e-3
    y = (np.arange(6) - 2.5) * 1e-3
    expected = -(x[None, :] ** 2 + y[:, None] ** 2) / 0.2
    assert np.allclose(surface.heights, expected, rtol=1e-14, atol=0)


def test_self_affine_rms_and_reproducibility():
    a = hs.generate.self_affine(grid=(64, 64), size=1e-3, rms_height=1e-6, seed=4)
    b = hs.generate.self_affine(grid=(64, 64), size=1e-3, rms_height=1e-6, seed=4)
    assert np.array_equal(a.heights, b.heights) and a.periodic
    assert a.statistics()["rms_height"] == pytest.approx(1e-6, rel=1e-12)
    assert "seed = 4" in a.source
    with pytest.raises(hs.InputError, match="exactly one"):
        hs.generate.self_affine(grid=(64, 64), size=1e-3)
    with pytest.raises(hs.InputError, match="H|hurst"):
        hs.generate.self_affine(grid=(64, 64), size=1e-3, rms_height=1e-6, hurst=1.5)


def test_wavy_periodic_and_flat():
    wavy = hs.generate.wavy(grid=(32, 32), size=1e-3, wavelength=0.5e-3, amplitude=1e-6)
    # h = -A (1 - cos cos) lies in [-2A, 0] and, sampled at 16 points per wavelength, spans most of it.
    assert wavy.periodic and -2e-6 <= wavy.heights.min() and wavy.heights.max() <= 0.0
    assert np.ptp(wavy.heights) > 1.9e-6
    assert not hs.generate.wavy(grid=32, size=1e-3, wavelength=0.3e-3, amplitude=1e-6).periodic
    assert np.all(hs.generate.flat(grid=16, size=1e-3).heights == 0)
    with pytest.raises(hs.InputError, match="grid"):
        hs.generate.flat(grid=(1, 4), size=1e-3)
