"""Synthetic surfaces, with the options of ``halfspace generate`` as keywords.

``grid`` is ``n`` (a profile of n points) or ``(nx, ny)``, ``size`` the
domain's extent in m, ``L`` or ``(lx, ly)``; the spacing is size / grid. Each
function returns a HeightMap whose heights are ``(ny, nx)`` (or ``(n,)``).
"""

from __future__ import annotations

from typing import Optional, Sequence, Union

from . import _core
from ._height_map import HeightMap

Grid = Union[int, Sequence[int]]
Size = Union[float, Sequence[float]]

__all__ = ["self_affine", "sphere", "cylinder", "wavy", "flat"]


def _layout(grid: Grid, size: Size):
    """(nx, ny, dimension, dx, dy) from the grid and size keywords."""
    cells = [grid] if isinstance(grid, int) else list(grid)
    extent = [size] if isinstance(size, (int, float)) else list(size)
    if len(cells) not in (1, 2) or any(int(n) != n or n < 2 for n in cells):
        raise _core.InputError(f"grid={grid!r} is invalid: give n or (nx, ny), at least 2 cells per axis")
    if len(extent) == 1 and len(cells) == 2:
        extent = extent * 2
    if len(extent) != len(cells) or any(not (s > 0) for s in extent):
        raise _core.InputError(f"size={size!r} is invalid: give a positive length or one per axis of grid (m)")
    if len(cells) == 1:
        return int(cells[0]), 1, 1, extent[0] / cells[0], 0.0
    return int(cells[0]), int(cells[1]), 2, extent[0] / cells[0], extent[1] / cells[1]


def _builtin(shape: str, grid: Grid, size: Size, radius=0.0, wavelength=0.0, amplitude=0.0, source=None,
             periodic=False) -> HeightMap:
    nx, ny, dimension, dx, dy = _layout(grid, size)
    heights = _core.builtin_surface(shape, nx, ny, dimension, dx, dy, radius, wavelength, amplitude)
    return HeightMap(heights, dx, dy if dimension == 2 else None, source=source or shape, periodic=periodic)


def sphere(*, grid: Grid, size: Size, radius: float) -> HeightMap:
    """A sphere (paraboloid) -(x^2 + y^2) / (2 radius), centred on the grid."""
    return _builtin("sphere", grid, size, radius=radius, source=f"sphere (radius = {radius} m)")


def cylinder(*, grid: Grid, size: Size, radius: float) -> HeightMap:
    """A cylinder -x^2 / (2 radius) with its axis along y, centred on the grid."""
    return _builtin("cylinder", grid, size, radius=radius, source=f"cylinder (radius = {radius} m)")


def wavy(*, grid: Grid, size: Size, wavelength: float, amplitude: float) -> HeightMap:
    """-amplitude (1 - cos(2 pi x / wavelength) cos(2 pi y / wavelength)); periodic
    when the domain holds a whole number of wavelengths."""
    nx, ny, dimension, dx, dy = _layout(grid, size)
    lengths = [nx * dx] + ([ny * dy] if dimension == 2 else [])
    periodic = all(abs(L / wavelength - round(L / wavelength)) <= 1e-9 * max(1.0, L / wavelength) for L in lengths)
    return _builtin("wavy", grid, size, wavelength=wavelength, amplitude=amplitude, periodic=periodic,
                    source=f"wavy (wavelength = {wavelength} m, amplitude = {amplitude} m)")


def flat(*, grid: Grid, size: Size) -> HeightMap:
    """A flat punch: zero heights."""
    return _builtin("flat", grid, size)


def self_affine(*, grid: Grid, size: Size, rms_height: Optional[float] = None, rms_slope: Optional[float] = None,
                hurst: float = 0.8, cutoff_short: Optional[float] = None, rolloff: Optional[float] = None,
                cutoff_long: Optional[float] = None, seed: int = 0) -> HeightMap:
    """A random self-affine surface, periodic on the domain, by Fourier filtering.

    Power spectrum C(q) ~ q^-(2 + 2H) between the wavelengths ``cutoff_short``
    (default 2 max(dx, dy)) and ``rolloff`` (default ``cutoff_long``), flat
    from there to ``cutoff_long`` (default the domain's longer side), zero
    outside; normalised to exactly one of ``rms_height`` (m) or ``rms_slope``.
    The same seed gives the same surface, bit for bit, for any thread count.
    """
    if (rms_height is None) == (rms_slope is None):
        raise _core.InputError("give exactly one of rms_height (m) and rms_slope")
    if not (isinstance(seed, int) and seed >= 0):
        raise _core.InputError(f"seed={seed!r} is invalid: the seed must be an integer, 0 or more")
    nx, ny, dimension, dx, dy = _layout(grid, size)
    heights, used = _core.self_affine(nx, ny, dimension, dx, dy, hurst, cutoff_short or 0.0, rolloff or 0.0,
                                      cutoff_long or 0.0, rms_height, rms_slope, seed)
    target = f"rms-height = {rms_height}" if rms_height is not None else f"rms-slope = {rms_slope}"
    source = (f"self-affine (H = {used['hurst']}, cutoff-short = {used['cutoff_short']} m, rolloff = "
              f"{used['rolloff']} m, cutoff-long = {used['cutoff_long']} m, {target}, seed = {seed})")
    return HeightMap(heights, dx, dy if dimension == 2 else None, source=source, periodic=True)
