# Type stubs of the compiled module halfspace._core (python/src/*.cpp).
# Users reach it through the package: halfspace.solve, halfspace.Result, ...
from typing import Any, Callable, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

__version__: str
git_hash: str

class InputError(ValueError):
    """Bad input or options: the message names the parameter, its value and the rule."""

class FileError(OSError):
    """A file that cannot be read or written: missing, unreadable, wrong layout."""

def subsurface_stress(
    result: "Result", depths: Sequence[float], nu: Optional[float], body: Optional[str]
) -> dict: ...

class Result:
    """The outcome of a solve. Field arrays are views of memory this object
    owns (no copies); each array keeps the Result alive."""

    @property
    def pressure(self) -> npt.NDArray[np.float64]:
        """Contact pressure (Pa), shaped like the surface, (ny, nx) or (n,)."""
    @property
    def gap(self) -> npt.NDArray[np.float64]:
        """Gap (m): initial gap + displacement - approach; 0 in contact."""
    @property
    def displacement(self) -> npt.NDArray[np.float64]:
        """Elastic surface displacement (m)."""
    @property
    def contact(self) -> npt.NDArray[np.bool_]:
        """True where the pressure is positive."""
    @property
    def residual_history(self) -> npt.NDArray[np.float64]: ...
    @property
    def heights(self) -> npt.NDArray[np.float64]:
        """The surface heights (m) the solve ran on."""
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def dx(self) -> float: ...
    @property
    def dy(self) -> float: ...
    @property
    def boundary(self) -> str: ...
    @property
    def e_star(self) -> float: ...
    @property
    def coating(self) -> Optional[dict[str, float]]:
        """A coated half-space's thickness (m), layer_E (Pa), layer_nu,
        substrate_E (Pa), substrate_nu; None for a homogeneous one."""
    @property
    def load_mode(self) -> str:
        """"force", "mean_pressure" or "approach"."""
    @property
    def load(self) -> float:
        """The imposed value, in the unit of load_mode."""
    @property
    def total_force(self) -> float:
        """N (N/m for a profile)."""
    @property
    def mean_pressure(self) -> float:
        """Pa."""
    @property
    def approach(self) -> float:
        """Rigid-body approach (m)."""
    @property
    def contact_fraction(self) -> float: ...
    @property
    def max_pressure(self) -> float: ...
    @property
    def hardness(self) -> Optional[float]:
        """The hardness cap H (Pa), None for an elastic solve."""
    @property
    def plastic_fraction(self) -> float:
        """Cells at the hardness cap over all cells (0 without a cap)."""
    @property
    def adhesion(self) -> Optional[dict]:
        """Adhesive solves: law, work_of_adhesion, range, stress, adhesive_force,
        interaction_fraction, repulsive_contact_fraction; None otherwise."""
    @property
    def iterations(self) -> int: ...
    @property
    def residual(self) -> float: ...
    @property
    def tolerance(self) -> float: ...
    @property
    def converged(self) -> bool: ...
    @property
    def status(self) -> str:
        """"converged", "iteration_limit", "breakdown" or "stopped" (by the progress callable)."""
    @property
    def message(self) -> str: ...
    @property
    def solver(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def solve_seconds(self) -> float: ...
    @property
    def warm_started(self) -> bool: ...
    @property
    def height_source(self) -> str: ...
    @property
    def preparation(self) -> list[str]: ...
    @property
    def threads(self) -> int: ...
    @property
    def statistics(self) -> dict[str, Any]:
        """contact_fraction, mean_gap, rms_gap, free_volume, clusters,
        cluster_sizes, surface_rms_height, surface_rms_slope."""
    @property
    def attributes(self) -> dict[str, Any]:
        """The result file's root attributes."""
    def save(self, path: str) -> None:
        """Writes the HDF5 file `halfspace solve` writes, and its XDMF sidecar (`.xdmf`, for ParaView) beside it."""
    # Friction: None for a frictionless result.
    @property
    def shear_x(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def shear_y(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def slip_x(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def slip_y(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def tangential_displacement_x(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def tangential_displacement_y(self) -> Optional[npt.NDArray[np.float64]]: ...
    @property
    def stick(self) -> Optional[npt.NDArray[np.bool_]]: ...
    @property
    def friction(self) -> Optional[dict[str, Any]]:
        """friction_coefficient, tangential_force, tangential_approach,
        stick_fraction, slip_fraction, dissipated_energy, gross_sliding,
        converged, status, message, iterations, residual, step."""

class History:
    """A tangential load history: one Result per step and the history table."""

    def __len__(self) -> int: ...
    def __getitem__(self, step: int) -> Result: ...
    @property
    def normal(self) -> Result: ...
    @property
    def converged(self) -> bool: ...
    @property
    def table(self) -> dict[str, npt.NDArray[np.float64]]:
        """step, Q_x, Q_y, delta_x, delta_y, stick_fraction, dissipated_energy."""
    def save(self, path: str) -> None:
        """Writes the history file, its CSV and its XDMF sidecar."""

class Sweep:
    """A load sweep: one Result per step and the summary table."""

    def __len__(self) -> int: ...
    def __getitem__(self, step: int) -> Result: ...
    @property
    def steps(self) -> list[Result]: ...
    @property
    def table(self) -> dict[str, npt.NDArray[np.float64]]:
        """load, mean_pressure, total_force, approach, contact_fraction,
        mean_gap, rms_gap, free_volume, max_pressure, clusters, iterations,
        residual, seconds, converged: one entry per step."""
    @property
    def load_mode(self) -> str: ...
    def to_pandas(self) -> Any:
        """The table as a pandas DataFrame (needs pandas)."""
    def save(self, path: str) -> None:
        """Writes the sweep's HDF5 file, and the CSV and the XDMF sidecar (`.xdmf`, for ParaView) beside it."""

def default_threads() -> int: ...
def max_threads() -> int: ...
def composite_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float: ...
def checked_composite_modulus(e_star: float) -> float: ...
def read_height_map(path: str, format: str, dataset: str, unit: Optional[str], window: Optional[str], invalid: str,
                    detrend: str, dx: Optional[float], dy: Optional[float], pad: float) -> dict[str, Any]: ...
def prepare(heights: npt.NDArray[np.float64], dx: float, dy: float, source: str, window: Optional[str],
            invalid: str, detrend: str, pad: float) -> dict[str, Any]: ...
def builtin_surface(shape: str, nx: int, ny: int, dimension: int, dx: float, dy: float, radius: float,
                    wavelength: float, amplitude: float) -> npt.NDArray[np.float64]: ...
def self_affine(nx: int, ny: int, dimension: int, dx: float, dy: float, hurst: float, cutoff_short: float,
                rolloff: float, cutoff_long: float, rms_height: Optional[float], rms_slope: Optional[float],
                seed: int) -> Tuple[npt.NDArray[np.float64], dict[str, float]]: ...
def surface_statistics(heights: npt.NDArray[np.float64], dx: float, dy: float, periodic: bool) -> dict[str, float]: ...
def solve(heights: npt.NDArray[np.float64], dx: float, dy: float, boundary: str, problem: dict[str, Any],
          initial_pressure: Optional[np.ndarray], progress: Optional[Callable[[int, float], Optional[bool]]],
          command_line: str, height_source: str, preparation: Sequence[str]) -> Result: ...
def sweep(heights: npt.NDArray[np.float64], dx: float, dy: float, boundary: str, problem: dict[str, Any],
          warm_start: bool, progress: Optional[Callable[[int, float], Optional[bool]]], command_line: str, height_source: str,
          preparation: Sequence[str]) -> Sweep: ...
def friction(heights: npt.NDArray[np.float64], dx: float, dy: float, boundary: str, problem: dict[str, Any],
             progress: Optional[Callable[[int, float], Optional[bool]]], command_line: str, height_source: str,
             preparation: Sequence[str]) -> History: ...
def read_result(path: str, step: int = -1) -> Result: ...
def lubricate(heights: npt.NDArray[np.float64], dx: float, dy: float, film: dict[str, Any],
              threads: Optional[int], trace: Optional[str]) -> Any:
    """The film of `film` (the library's option names, lubrication_option_names; None: not given): its fields
    (numpy arrays) and numbers, as halfspace.Film holds them, or with speeds a list of them, one per speed, or
    with time_step a dict of the steps' films and the run's status (python/src/lubricate.cpp)."""
def paper_reproduce(test: int, load: float) -> dict[str, Any]: ...
