"""precision= (``--precision``): the mixed solve gives the double one's pressure."""
import numpy as np
import pytest

import halfspace as hs


@pytest.mark.parametrize("boundary", ["periodic", "free"])
def test_mixed_precision_gives_the_double_pressure(boundary):
    # Within 10x the tolerance (1e-10) of the peak pressure, as the library's
    # tests ask (tests/solvers/mixed_precision_test.cpp).
    surface = hs.generate.self_affine(grid=(64, 64), size=64e-6, hurst=0.8, rms_slope=0.1, seed=3)
    both = [hs.solve(surface, e_star=1e9, mean_pressure=4e6, boundary=boundary, precision=precision,
                     fft_planning="estimate", threads=1) for precision in ("double", "mixed")]
    assert all(result.converged for result in both), [result.message for result in both]
    assert np.abs(both[1].pressure - both[0].pressure).max() <= 1e-9 * both[0].pressure.max()


def test_mixed_precision_is_refused_by_the_adhesive_solver():
    surface = hs.generate.sphere(grid=(16, 16), size=1e-3, radius=0.01)
    with pytest.raises(hs.InputError, match="precision=mixed does not apply to the adhesive solver"):
        hs.solve(surface, e_star=1e9, approach=1e-7, adhesion="md", work_of_adhesion=0.05, adhesion_range=1e-6,
                 precision="mixed")
