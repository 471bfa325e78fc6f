"""Arrays cross the boundary without copies: float64 C-contiguous inputs are
used in place, and a Result's fields are views of the memory it owns."""

import gc
import weakref

import numpy as np

import halfspace as hs


def small_solve(heights=None):
    if heights is None:
        heights = hs.generate.sphere(grid=(32, 32), size=1e-3, radius=0.01).heights
    return hs.solve(heights, dx=1e-3 / 32, e_star=1e9, force=0.1, fft_planning="estimate", threads=1)


def test_float64_input_is_not_copied():
    heights = hs.generate.sphere(grid=(32, 32), size=1e-3, radius=0.01).heights
    surface = hs.HeightMap(heights, 1e-3 / 32)
    assert surface.heights is heights
    result = small_solve(heights)
    assert np.shares_memory(result.heights, heights)


def test_other_dtypes_are_converted_once():
    heights = hs.generate.sphere(grid=(32, 32), size=1e-3, radius=0.01).heights
    as_float32 = heights.astype(np.float32)
    surface = hs.HeightMap(as_float32, 1e-3 / 32)
    assert surface.heights.dtype == np.float64 and surface.heights.flags.c_contiguous
    transposed = hs.HeightMap(np.asfortranarray(heights), 1e-3 / 32)
    assert transposed.heights.flags.c_contiguous and np.array_equal(transposed.heights, heights)


def test_fields_are_views_owned_by_the_result():
    result = small_solve()
    first, second = result.pressure, result.pressure
    assert np.shares_memory(first, second)  # the same C++ buffer each time, not a copy
    assert not first.flags.owndata
    assert first.base is not None
    # The array keeps the Result alive: drop every other reference.
    expected = first.copy()
    owner = weakref.ref(result) if hasattr(result, "__weakref__") else None
    del result, second
    gc.collect()
    assert np.array_equal(first, expected)
    if owner is not None:
        assert owner() is not None


def test_fields_are_writable_views_of_one_buffer():
    result = small_solve()
    view = result.gap
    view[0, 0] = 123.0
    assert result.gap[0, 0] == 123.0


def test_read_heights_own_their_memory_without_copy(data_dir):
    surface = hs.read_height_map(data_dir / "di-5-crop-48x64.h5")
    assert surface.heights.dtype == np.float64 and surface.heights.flags.c_contiguous
    # The reader's buffer, handed over with a capsule: no second copy on the way.
    assert surface.heights.base is not None
