"""HeightMap and read_height_map: measured or generated surfaces in metres."""

from __future__ import annotations

import os
from typing import Optional, Sequence, Tuple, Union

import numpy as np

from . import _core
from ._topography import NATIVE_EXTENSIONS, read_with_surface_topography

Window = Union[str, Sequence[int], None]
Cells = Union[str, int, Sequence[int], None]


def _window_text(window: Window) -> Optional[str]:
    """The library's window syntax "I0,J0,NX,NY" (or "I0,NX") from a tuple."""
    if window is None or isinstance(window, str):
        return window
    return ",".join(str(int(v)) for v in window)


def _cells_text(cells: Cells) -> Optional[str]:
    """The library's resample syntax "NXxNY" (or "N") from a tuple or an int."""
    if cells is None or isinstance(cells, str):
        return cells
    if isinstance(cells, (int, np.integer)):
        return str(int(cells))
    return "x".join(str(int(v)) for v in cells)


class HeightMap:
    """A surface height map: heights in metres on a regular grid.

    ``heights`` is a ``(ny, nx)`` array (rows along y) or a ``(n,)`` profile;
    ``dx`` and ``dy`` are the spacings in metres (``dy`` defaults to ``dx`` for
    a map and is None for a profile). float64 C-contiguous arrays are kept as
    they are, without a copy; other dtypes and layouts are converted once.
    Non-finite heights mark invalid points; :meth:`prepare` removes them.
    """

    def __init__(self, heights, dx: float, dy: Optional[float] = None, *, source: Optional[str] = None,
                 preparation: Sequence[str] = (), periodic: bool = False):
        array = np.ascontiguousarray(heights, dtype=np.float64)
        if array.ndim not in (1, 2):
            raise _core.InputError(f"heights must be a 1D profile or a 2D map, got an array of shape {array.shape}")
        for name, value in (("dx", dx), ("dy", dy)):
            if value is not None and not (np.isfinite(value) and value > 0):
                raise _core.InputError(f"{name}={value!r} is invalid: the spacing must be positive and finite (m)")
        if dx is None:
            raise _core.InputError("dx is required: the spacing along x (m)")
        if array.ndim == 1 and dy is not None:
            raise _core.InputError("dy does not apply to a 1D profile")
        self.heights = array
        self.dx = float(dx)
        self.dy = None if array.ndim == 1 else float(dx if dy is None else dy)
        self.source = source if source is not None else f"array {'x'.join(map(str, array.shape[::-1]))} from Python"
        self.preparation = tuple(preparation)
        self.periodic = bool(periodic)

    @property
    def shape(self) -> Tuple[int, ...]:
        """``(ny, nx)`` or ``(n,)``."""
        return self.heights.shape

    @property
    def dimension(self) -> int:
        return self.heights.ndim

    @property
    def size(self) -> Tuple[float, ...]:
        """The domain's extent (m): ``(lx, ly)`` or ``(lx,)``."""
        if self.dimension == 1:
            return (self.heights.shape[0] * self.dx,)
        return (self.heights.shape[1] * self.dx, self.heights.shape[0] * self.dy)

    def prepare(self, *, window: Window = None, invalid: str = "refuse", detrend: str = "none",
                resample: Cells = None, pad: float = 1.0) -> "HeightMap":
        """A new map after the library's preparation steps, in this order:
        window ``(i0, j0, nx, ny)`` (or ``(i0, nx)``), invalid points
        (``"refuse"``, ``"fill"`` or ``"crop"``), detrending (``"none"``,
        ``"mean"``, ``"plane"``, ``"curvature"``), resampling onto ``(nx,
        ny)`` cells (or ``n`` for a profile) over the same lengths (linear
        interpolation where finer, cell means where coarser) and padding
        (``pad`` > 1, free boundaries). Each step that changes the map adds
        a line to ``preparation``."""
        prepared = _core.prepare(self.heights, self.dx, self.dy or 0.0, self.source, _window_text(window), invalid,
                                 detrend, _cells_text(resample), pad)
        return HeightMap._from_core(prepared, preparation=self.preparation, periodic=self.periodic)

    def statistics(self, periodic: Optional[bool] = None) -> dict:
        """rms height (m) and rms slope; the slope is spectral on a periodic
        surface, by finite differences otherwise (default: ``self.periodic``)."""
        periodic = self.periodic if periodic is None else periodic
        return _core.surface_statistics(self.heights, self.dx, self.dy or 0.0, periodic)

    @classmethod
    def _from_core(cls, prepared: dict, preparation: Sequence[str] = (), periodic: bool = False) -> "HeightMap":
        heights = prepared["heights"]
        return cls(heights, prepared["dx"], prepared["dy"] if heights.ndim == 2 else None, source=prepared["source"],
                   preparation=tuple(preparation) + tuple(prepared["preparation"]), periodic=periodic)

    def __repr__(self) -> str:
        grid = "x".join(map(str, self.shape[::-1]))
        spacing = f"dx={self.dx:g} m" if self.dimension == 1 else f"dx={self.dx:g} m, dy={self.dy:g} m"
        steps = f", {len(self.preparation)} preparation steps" if self.preparation else ""
        return f"HeightMap({grid}, {spacing}, source={self.source!r}{steps})"


def read_height_map(path: Union[str, os.PathLike], *, format: str = "auto", unit: Optional[str] = None,
                    window: Window = None, invalid: str = "refuse", detrend: str = "none",
                    dx: Optional[float] = None, dy: Optional[float] = None, dataset: Optional[str] = None,
                    resample: Cells = None, pad: float = 1.0) -> HeightMap:
    """Reads a height map and prepares it as ``halfspace solve --height-map`` does.

    Formats read natively (``format="auto"`` chooses by extension): HDF5 and
    NetCDF-4 (``.h5 .hdf5 .nc``; ``dataset`` names the dataset, default
    ``/height``), NumPy ``.npy``, text matrices (``.txt .csv .dat .asc``),
    Dektak profiles, ISO 25178 X3P and Gwyddion GSF. ``unit`` is the length
    unit of files that state none ("um", "nm", ...). ``dx``/``dy`` override
    or supply the spacing (m). The preparation keywords are
    :meth:`HeightMap.prepare`'s. Other instrument formats (.sur, .plu, .opd,
    .di, MetroPro .dat, ...) are read through the SurfaceTopography package
    where it is installed (``format="surfacetopography"`` forces it).

    Raises FileError (an OSError) for an unreadable file, InputError (a
    ValueError) for a bad option.
    """
    path = os.fspath(path)
    extension = os.path.splitext(path)[1].lower()
    wants_fallback = format.lower() in ("surfacetopography", "surface-topography")
    if wants_fallback or (format == "auto" and extension not in NATIVE_EXTENSIONS):
        return read_with_surface_topography(path, unit=unit, window=_window_text(window), invalid=invalid,
                                            detrend=detrend, dx=dx, dy=dy, resample=_cells_text(resample), pad=pad,
                                            reason=None if wants_fallback else extension)
    try:
        prepared = _core.read_height_map(path, format, dataset or "", unit, _window_text(window), invalid, detrend,
                                         _cells_text(resample), dx, dy, pad)
    except _core.FileError:
        # A .dat file is a text matrix to halfspace and a Zygo MetroPro file
        # to its instrument: a binary one goes to SurfaceTopography.
        if format == "auto" and extension == ".dat" and _looks_binary(path):
            return read_with_surface_topography(path, unit=unit, window=_window_text(window), invalid=invalid,
                                                detrend=detrend, dx=dx, dy=dy, resample=_cells_text(resample), pad=pad,
                                                reason=extension)
        raise
    return HeightMap._from_core(prepared)


def _looks_binary(path: str) -> bool:
    try:
        with open(path, "rb") as file:
            return b"\0" in file.read(4096)
    except OSError:
        return False
