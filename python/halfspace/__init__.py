"""halfspace: elastic contact of rough surfaces (normal, adhesive, frictional)
and lubricated films, from Python.

The engine is the C++ library of this repository (Polonsky-Keer with
FFT-based influence operators); this package hands it numpy arrays and gives
numpy arrays back without copying them.

>>> import halfspace as hs
>>> surface = hs.generate.self_affine(grid=(256, 256), size=1e-3, rms_slope=0.1, seed=1)
>>> result = hs.solve(surface, e_star=1e9, mean_pressure=1e6, boundary="periodic")
>>> result.contact_fraction, result.pressure.shape

See docs/python.md for the whole API.
"""

import os as _os

# OpenMP threads that wait for work spin on a core unless the wait policy is
# passive; a solve on a shared machine then runs many times slower (the
# `halfspace` program sets it too). The OpenMP runtime reads it when the
# extension is loaded, so it is set before the import below.
_os.environ.setdefault("OMP_WAIT_POLICY", "passive")

from . import _core  # noqa: E402
from ._core import FileError, History, InputError, Result, Sweep  # noqa: E402
from ._height_map import HeightMap, read_height_map  # noqa: E402
from ._lubricate import Film, FilmHistory, StribeckCurve, lubricate, stribeck  # noqa: E402
from ._solve import composite_modulus, history, read_result, solve, subsurface_stress, sweep  # noqa: E402
from . import generate, paper  # noqa: E402

__version__ = _core.__version__

__all__ = [
    "FileError",
    "Film",
    "FilmHistory",
    "HeightMap",
    "History",
    "InputError",
    "Result",
    "StribeckCurve",
    "Sweep",
    "composite_modulus",
    "generate",
    "history",
    "lubricate",
    "paper",
    "read_height_map",
    "read_result",
    "solve",
    "stribeck",
    "subsurface_stress",
    "sweep",
]


def _sweep_to_pandas(self):
    """The summary table as a pandas DataFrame (needs pandas)."""
    try:
        import pandas
    except ImportError as error:
        raise ImportError("Sweep.to_pandas needs pandas: pip install pandas") from error
    return pandas.DataFrame(self.table)


def _sweep_steps(self):
    """Every step as a Result, in order."""
    return [self[k] for k in range(len(self))]


Sweep.to_pandas = _sweep_to_pandas
Sweep.steps = property(_sweep_steps)
