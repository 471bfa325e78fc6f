"""lubricate: a lubricated film (rigid Reynolds or EHL) from Python, as ``halfspace lubricate``."""

from __future__ import annotations

from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _core
from ._height_map import HeightMap
from ._solve import _coating, _surface

Velocity = Union[float, Sequence[float]]


# E* of the elastic film's body. The contact solves take the body through
# the library's problem builder; the lubrication binding takes E* itself.
def _material(e_star, E1, nu1, E2, nu2) -> float:
    constants = {"E1": E1, "nu1": nu1, "E2": E2, "nu2": nu2}
    given = [name for name, value in constants.items() if value is not None]
    if e_star is not None and given:
        raise _core.InputError(f"e_star cannot be combined with {', '.join(given)}: give either e_star or all of "
                               "E1, nu1, E2, nu2")
    if e_star is not None:
        return float(e_star)
    if len(given) < 4:
        missing = [name for name in constants if constants[name] is None]
        raise _core.InputError(f"incomplete material: missing {', '.join(missing)} (give all of E1, nu1, E2, nu2, "
                               "or e_star)")
    return _core.composite_modulus(E1, nu1, E2, nu2)


class Film:
    """A solved lubricated film. Field arrays are numpy arrays shaped like the
    surface ((ny, nx) or (n,)); numbers are SI.

    Attributes: ``model`` ("rigid" or "elastic"), ``converged``, ``status``
    ("converged", "iteration_limit" or "failure"), ``message``; fields
    ``pressure`` (Pa), ``film`` (h, m), ``fluid_fraction`` (theta),
    ``deformation`` (m, elastic only, else None), ``shear_x``, ``shear_y``
    (Pa, the film's shear on the lower surface); numbers ``load`` (N, N/m on a
    profile), ``mean_pressure`` (Pa), ``separation`` (m: the minimum film of a
    rigid film, the offset h0 of an elastic one), ``central_film_thickness``,
    ``minimum_film_thickness`` (m), ``max_pressure`` (Pa),
    ``cavitated_fraction``, ``iterations`` (sweeps or Newton steps),
    ``film_solves``, ``relative_residual``, ``solve_seconds``, ``inflow``,
    ``outflow`` (rigid only, else None), ``load_error`` (elastic only),
    ``friction_force`` and ``couette_friction_force`` ((x, y), N; N/m),
    ``friction_coefficient``, ``limited_fraction`` (nodes whose Couette
    stress a shear limit lowered); elastic films also ``e_star``,
    ``piezoviscosity``, ``roelands_index`` (the z in force),
    ``compressibility`` and ``couette_scheme`` (None for a rigid film)."""

    model: str
    status: str
    message: str
    converged: bool
    pressure: npt.NDArray[np.float64]
    film: npt.NDArray[np.float64]
    fluid_fraction: npt.NDArray[np.float64]
    deformation: Optional[npt.NDArray[np.float64]]
    shear_x: npt.NDArray[np.float64]
    shear_y: npt.NDArray[np.float64]
    load: float
    mean_pressure: float
    separation: float
    central_film_thickness: float
    minimum_film_thickness: float
    max_pressure: float
    cavitated_fraction: float
    iterations: int
    film_solves: int
    relative_residual: float
    solve_seconds: float
    inflow: Optional[float]
    outflow: Optional[float]
    load_error: Optional[float]
    friction_force: Tuple[float, float]
    couette_friction_force: Tuple[float, float]
    friction_coefficient: float
    limited_fraction: float

    # Elastic films only (None for a rigid one).
    e_star: Optional[float] = None
    piezoviscosity: Optional[str] = None
    roelands_index: Optional[float] = None
    compressibility: Optional[str] = None
    couette_scheme: Optional[str] = None

    def __init__(self, values: Mapping[str, Any]):
        self.__dict__.update(values)

    def __repr__(self) -> str:
        return (f"<halfspace.Film {self.model} {self.status}: load {self.load:.6g}, "
                f"central film {self.central_film_thickness:.6g} m, minimum {self.minimum_film_thickness:.6g} m>")


def _velocity(value: Optional[Velocity], name: str) -> list:
    if value is None:
        return []
    array = np.atleast_1d(np.asarray(value, dtype=np.float64))
    if array.ndim != 1 or array.size not in (1, 2):
        raise _core.InputError(f"{name} must be UX or (UX, UY) in m/s")
    return [float(v) for v in array]


def _optional_float(value, name: str) -> Optional[float]:
    if value is None:
        return None
    if np.ndim(value) != 0:
        raise _core.InputError(f"{name} must be one number")
    return float(value)


def lubricate(surface: Union[HeightMap, np.ndarray], *, viscosity: float, entrainment_velocity: Velocity,
              dx: Optional[float] = None, dy: Optional[float] = None, sliding_velocity: Optional[Velocity] = None,
              separation: Optional[float] = None, force: Optional[float] = None, inlet_pressure: float = 0.0,
              outlet_pressure: float = 0.0, side_pressure: float = 0.0, periodic_x: bool = False,
              periodic_y: bool = False, supply_fluid_fraction: float = 1.0, tol: Optional[float] = None,
              max_iter: Optional[int] = None, e_star: Optional[float] = None, E1: Optional[float] = None,
              nu1: Optional[float] = None, E2: Optional[float] = None, nu2: Optional[float] = None,
              coating: Optional[Mapping[str, float]] = None, boundary: str = "free",
              pressure_viscosity: Optional[float] = None, piezoviscosity: Optional[str] = None,
              roelands_index: Optional[float] = None, compressibility: Optional[str] = None,
              couette_scheme: Optional[str] = None, eyring_stress: Optional[float] = None,
              limiting_shear_stress: Optional[float] = None,
              limiting_shear_slope: Optional[float] = None) -> Film:
    """Solves the Reynolds film between a surface and a flat, as ``halfspace lubricate``.

    surface: a HeightMap, or a 1D/2D array of heights (m, ``(ny, nx)``) with
        ``dx`` (and ``dy``). The film is ``h = separation + max z - z``
        (rigid) or ``h0 + max z - z + K p`` (elastic).
    viscosity: ambient viscosity eta0 (Pa s). entrainment_velocity: the mean
        of the two surfaces' velocities, UX or (UX, UY) (m/s).
        sliding_velocity: upper minus lower surface velocity (m/s), for the
        film's shear (it carries no load).
    separation / force: exactly one: the rigid film's minimum thickness (m),
        or the load it carries (N; N/m on a profile; the separation is
        found). An elastic film takes force only.
    inlet_pressure, outlet_pressure (at the first and last x), side_pressure
        (at the first and last y of a map): imposed pressures (Pa, >= 0);
        periodic_x / periodic_y: the film repeats along that axis instead;
        supply_fluid_fraction: theta of the lubricant at the fixed-pressure
        nodes (1 flooded, < 1 starved). Cavitation (p >= 0, 0 <= theta <= 1,
        p (1 - theta) = 0) is mass conserving (Elrod-Adams p-theta).
    tol, max_iter: the rigid solver's relative mass residual and sweeps
        (None: 1e-11, 2000000), or the elastic film's residual and Newton
        steps (None: 1e-8, 100).
    e_star, or E1, nu1, E2, nu2, or coating (a mapping with thickness,
        layer_E, layer_nu, substrate_E, substrate_nu as in :func:`solve`):
        the film is elastohydrodynamic, with boundary ("free" or
        "periodic") the elastic half-space's; pressure_viscosity alpha
        (1/Pa), piezoviscosity ("none", "barus", "roelands"; None: barus
        when alpha is given), roelands_index (z; None: from alpha),
        compressibility ("none", "dowson-higginson"; None: Dowson-Higginson),
        couette_scheme ("first-order", "second-order").
    eyring_stress (tau0, Pa), limiting_shear_stress (tau_L0, Pa),
        limiting_shear_slope (gamma): the film's Couette shear stress is
        tau0 asinh(tau_N / tau0) (Eyring) and/or at most tau_L0 + gamma p;
        the pressure and film stay the Newtonian solution.

    Returns a :class:`Film`. Non-convergence is not an exception (see
    ``Film.converged`` and ``.message``); bad options raise InputError naming
    the keyword, its value and the rule. The GIL is released while solving.
    """
    height_map = _surface(surface, dx, dy)
    elastic_given = any(value is not None for value in (e_star, E1, nu1, E2, nu2, coating))
    layers = _coating(coating, e_star, E1, nu1, E2, nu2)
    modulus = None
    if elastic_given and layers is None:
        modulus = _material(e_star, E1, nu1, E2, nu2)
    if entrainment_velocity is None:
        raise _core.InputError("entrainment_velocity= is needed: UX or (UX, UY) in m/s")
    limits = {"eyring_stress": eyring_stress, "limiting_shear_stress": limiting_shear_stress,
              "limiting_shear_slope": limiting_shear_slope}
    limit_values = [0.0 if value is None else _optional_float(value, name) for name, value in limits.items()]
    values = _core.lubricate(
        height_map.heights, height_map.dx, height_map.dy or 0.0, float(viscosity),
        _velocity(entrainment_velocity, "entrainment_velocity"), _velocity(sliding_velocity, "sliding_velocity"),
        _optional_float(separation, "separation"), _optional_float(force, "force"), float(inlet_pressure),
        float(outlet_pressure), float(side_pressure), bool(periodic_x), bool(periodic_y),
        float(supply_fluid_fraction), _optional_float(tol, "tol"), None if max_iter is None else int(max_iter),
        modulus, layers, boundary, _optional_float(pressure_viscosity, "pressure_viscosity"), piezoviscosity,
        _optional_float(roelands_index, "roelands_index"), compressibility, couette_scheme, *limit_values)
    return Film(values)
