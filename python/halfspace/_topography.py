"""Instrument formats halfspace does not read itself, through SurfaceTopography.

SurfaceTopography (the contact.engineering readers) knows some 35 formats
of profilometers, AFMs and interferometers. Where it is installed,
read_height_map hands it such files and converts its topography to
halfspace's conventions: heights and spacings in metres, heights as
(ny, nx) rows along y (SurfaceTopography's arrays are (nx, ny)), and its
mask of undefined data as invalid points (NaN), which the preparation then
refuses, fills or crops.
"""

from __future__ import annotations

from typing import Optional

import numpy as np

from . import _core

# Extensions the library's own readers take (io/height_map_reader.hpp).
NATIVE_EXTENSIONS = frozenset(
    [".h5", ".hdf5", ".hdf", ".he5", ".nc", ".nc4", ".npy", ".txt", ".csv", ".dat", ".asc", ".x3p", ".gsf"])

# SurfaceTopography's unit names in metres.
_UNITS = {"km": 1e3, "m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "nm": 1e-9,
          "Å": 1e-10, "A": 1e-10, "pm": 1e-12}


def _metres_per(unit, path: str) -> float:
    if unit is None:
        raise _core.FileError(f"height map {path}: SurfaceTopography found no length unit; pass unit=")
    try:
        return _UNITS[str(unit)]
    except KeyError:
        raise _core.FileError(f"height map {path}: unknown length unit {unit!r} from SurfaceTopography") from None


def read_with_surface_topography(path: str, *, unit: Optional[str], window: Optional[str], invalid: str,
                                 detrend: str, dx: Optional[float], dy: Optional[float], resample: Optional[str],
                                 pad: float, reason: Optional[str]):
    from ._height_map import HeightMap

    try:
        import SurfaceTopography
    except ImportError:
        why = f"halfspace does not read '{reason}' files itself" if reason else "format='surfacetopography' was asked"
        raise _core.FileError(
            f"cannot read height map {path}: {why}; install the SurfaceTopography package "
            f"(pip install SurfaceTopography) to read it, or convert it to HDF5, NumPy, X3P or GSF") from None

    try:
        reader = SurfaceTopography.open_topography(path)
        channel = reader.default_channel
        metres = _metres_per(unit if unit is not None else channel.unit, path)
        sizes = channel.physical_sizes
        if sizes is None or any(s is None for s in np.atleast_1d(sizes)):
            spacing = [dx] if len(channel.nb_grid_pts) == 1 else [dx, dy]
            if any(s is None for s in spacing):
                raise _core.FileError(f"height map {path} does not state its spacing: pass dx= and dy= (m)")
            sizes = tuple(n * s / metres for n, s in zip(channel.nb_grid_pts, spacing))
            topography = reader.topography(channel_index=channel.index, physical_sizes=sizes)
        else:
            topography = reader.topography(channel_index=channel.index)
    except _core.FileError:
        raise
    except Exception as error:  # the readers raise many types; the message is what matters
        raise _core.FileError(f"cannot read height map {path} with SurfaceTopography: {error}") from error

    heights = topography.heights()
    mask = np.ma.getmaskarray(heights)
    values = np.ma.getdata(heights).astype(np.float64) * metres
    values[mask] = np.nan
    sizes = np.atleast_1d(topography.physical_sizes).astype(float) * metres
    grid = np.atleast_1d(topography.nb_grid_pts)
    if values.ndim == 2:
        values = np.ascontiguousarray(values.T)  # (nx, ny) -> (ny, nx)
        spacing_x, spacing_y = sizes[0] / grid[0], sizes[1] / grid[1]
    else:
        spacing_x, spacing_y = sizes[0] / grid[0], None
    if dx is not None:
        spacing_x = dx
    if dy is not None and values.ndim == 2:
        spacing_y = dy
    source = f"{path} (SurfaceTopography, {type(reader).__name__})"
    surface = HeightMap(values, spacing_x, spacing_y, source=source)
    return surface.prepare(window=window, invalid=invalid, detrend=detrend, resample=resample, pad=pad)
