"""lubricate: a lubricated film (rigid Reynolds, EHL or mixed) from Python, as ``halfspace lubricate``;
stribeck: the mixed film's Stribeck curve, as ``halfspace lubricate --mixed --speeds``."""

from __future__ import annotations

import inspect
import os
from typing import Any, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _core
from ._height_map import HeightMap
from ._solve import _coating, _surface

Velocity = Union[float, Sequence[float]]


class Film:
    """A solved lubricated film. Field arrays are numpy arrays shaped like the
    surface ((ny, nx) or (n,)); numbers are SI.

    Attributes: ``model`` ("rigid", "elastic" or "mixed"), ``converged``, ``status``
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
    ``compressibility`` and ``couette_scheme`` (None for a rigid film).

    A mixed film (``mixed=True``) also has the fields ``fluid_pressure`` and
    ``contact_pressure`` (Pa; ``pressure`` is their sum) and the numbers
    ``contact_load_fraction``, ``fluid_load``, ``contact_load``,
    ``contact_area`` (m^2; m on a profile), ``contact_area_fraction``,
    ``fluid_friction_force`` and ``contact_friction_force`` ((x, y), their
    sum is ``friction_force``), ``contact_friction`` (Coulomb mu),
    ``boundary_film`` (m), ``complementarity_error`` and
    ``entrainment_speed`` (m/s); its friction is given as forces only
    (``shear_x``, ``shear_y``, ``couette_friction_force`` and
    ``limited_fraction`` are None). ``separation`` is its offset h0."""

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

    # Mixed films only (None otherwise).
    fluid_pressure: Optional[npt.NDArray[np.float64]] = None
    contact_pressure: Optional[npt.NDArray[np.float64]] = None
    contact_load_fraction: Optional[float] = None
    fluid_load: Optional[float] = None
    contact_load: Optional[float] = None
    contact_area: Optional[float] = None
    contact_area_fraction: Optional[float] = None
    fluid_friction_force: Optional[Tuple[float, float]] = None
    contact_friction_force: Optional[Tuple[float, float]] = None
    contact_friction: Optional[float] = None
    boundary_film: Optional[float] = None
    complementarity_error: Optional[float] = None
    entrainment_speed: Optional[float] = None
    hersey_number: Optional[float] = None  # a Stribeck curve's films only

    # Elastic films only (None for a rigid one).
    e_star: Optional[float] = None
    piezoviscosity: Optional[str] = None
    roelands_index: Optional[float] = None
    compressibility: Optional[str] = None
    couette_scheme: Optional[str] = None

    def __init__(self, values: Mapping[str, Any]):
        self.__dict__.update(values)

    def __repr__(self) -> str:
        contact = "" if self.contact_load_fraction is None else f", contact share {self.contact_load_fraction:.4g}"
        return (f"<halfspace.Film {self.model} {self.status}: load {self.load:.6g}, "
                f"central film {self.central_film_thickness:.6g} m, minimum {self.minimum_film_thickness:.6g} m"
                f"{contact}>")


class StribeckCurve:
    """A Stribeck curve: the mixed film at each entrainment speed, in the
    order given (each solve starting from the previous film), as the CSV of
    ``halfspace lubricate --mixed --speeds ... --stribeck FILE``.

    Columns (numpy arrays, one value per speed): ``entrainment_speed`` (m/s),
    ``hersey_number`` (eta0 |U| / w', w' the load per unit width),
    ``friction_coefficient``, ``fluid_friction`` and ``contact_friction``
    (|force|, N/m on a profile), ``contact_load_fraction``,
    ``contact_area_fraction``, ``central_film_thickness``,
    ``minimum_film_thickness`` (m), ``newton_steps``; ``status`` (a list of
    str); ``films`` (one :class:`Film` per speed); ``converged`` (every
    film converged)."""

    COLUMNS = ("entrainment_speed", "hersey_number", "friction_coefficient", "fluid_friction", "contact_friction",
               "contact_load_fraction", "contact_area_fraction", "central_film_thickness", "minimum_film_thickness",
               "status", "newton_steps")

    def __init__(self, films: Sequence[Mapping[str, Any]]):
        self.films = [Film(values) for values in films]
        f = self.films
        self.entrainment_speed = np.array([film.entrainment_speed for film in f])
        self.hersey_number = np.array([film.hersey_number for film in f])
        self.friction_coefficient = np.array([film.friction_coefficient for film in f])
        self.fluid_friction = np.array([np.hypot(*film.fluid_friction_force) for film in f])
        self.contact_friction = np.array([np.hypot(*film.contact_friction_force) for film in f])
        self.contact_load_fraction = np.array([film.contact_load_fraction for film in f])
        self.contact_area_fraction = np.array([film.contact_area_fraction for film in f])
        self.central_film_thickness = np.array([film.central_film_thickness for film in f])
        self.minimum_film_thickness = np.array([film.minimum_film_thickness for film in f])
        self.newton_steps = np.array([film.iterations for film in f], dtype=np.int64)
        self.status = [film.status for film in f]
        self.converged = all(film.converged for film in f)

    def __len__(self) -> int:
        return len(self.films)

    @property
    def table(self) -> dict:
        """The columns by name (the CSV's header)."""
        return {name: getattr(self, name) for name in self.COLUMNS}

    def to_pandas(self):
        """The curve as a pandas DataFrame (needs pandas)."""
        try:
            import pandas
        except ImportError as error:
            raise ImportError("StribeckCurve.to_pandas needs pandas: pip install pandas") from error
        return pandas.DataFrame(self.table)

    def __repr__(self) -> str:
        return (f"<halfspace.StribeckCurve {len(self)} speeds, friction coefficient "
                f"{self.friction_coefficient.min():.4g} to {self.friction_coefficient.max():.4g}>")


class FilmHistory:
    """A transient rigid film (``time_step=``): the film at each step, the
    initial (steady) state first, as ``halfspace lubricate --time-step``
    writes them (its /steps groups and CSV history).

    ``films`` (one :class:`Film` per step, each with ``step``, ``time`` (s)
    and ``fluid_volume`` (m^3; m^2 on a profile: the fluid the unknown
    nodes hold)); columns (numpy arrays, one value per step) ``step``,
    ``time``, ``separation``, ``load``, ``minimum_film_thickness``,
    ``max_pressure``, ``cavitated_fraction``, ``fluid_volume``, ``inflow``,
    ``outflow``, ``film_solves``; ``converged``, ``status`` and ``message``
    of the run (the first step that failed), ``steps_done``, ``time_step``,
    ``time_scheme``."""

    COLUMNS = ("step", "time", "separation", "load", "minimum_film_thickness", "max_pressure",
               "cavitated_fraction", "fluid_volume", "inflow", "outflow", "film_solves")

    def __init__(self, values: Mapping[str, Any]):
        self.films = [Film(film) for film in values["films"]]
        for name in self.COLUMNS:
            setattr(self, name, np.array([getattr(film, name) for film in self.films]))
        self.converged = bool(values["converged"])
        self.status = values["status"]
        self.message = values["message"]
        self.steps_done = int(values["steps_done"])
        self.time_step = float(values["time_step"])
        self.time_scheme = values["time_scheme"]

    def __len__(self) -> int:
        return len(self.films)

    @property
    def table(self) -> dict:
        """The columns by name (the CSV's header)."""
        return {name: getattr(self, name) for name in self.COLUMNS}

    def __repr__(self) -> str:
        return (f"<halfspace.FilmHistory {self.status}: {len(self) - 1} steps of {self.time_step:.6g} s, "
                f"separation {self.separation[0]:.6g} -> {self.separation[-1]:.6g} m>")


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


def _sequence(values, message: str) -> Optional[list]:
    """A non-empty 1D sequence of floats, or None; InputError(message) otherwise."""
    if values is None:
        return None
    array = np.atleast_1d(np.asarray(values, dtype=np.float64))
    if array.ndim != 1 or array.size == 0:
        raise _core.InputError(message)
    return [float(v) for v in array]


# The arguments of _core.lubricate from the keywords of lubricate and
# stribeck (one list, so that both map them alike).
def _arguments(surface, *, viscosity: float, entrainment_velocity: Velocity,
              dx: Optional[float] = None, dy: Optional[float] = None, sliding_velocity: Optional[Velocity] = None,
              separation: Optional[float] = None, force: Optional[float] = None, inlet_pressure: float = 0.0,
              outlet_pressure: float = 0.0, side_pressure: float = 0.0, periodic_x: bool = False,
              periodic_y: bool = False, supply_fluid_fraction: float = 1.0, tol: Optional[float] = None,
              max_iter: Optional[int] = None, e_star: Optional[float] = None, E1: Optional[float] = None,
              nu1: Optional[float] = None, E2: Optional[float] = None, nu2: Optional[float] = None,
              coating: Optional[Mapping[str, float]] = None, boundary: Optional[str] = None,
              pressure_viscosity: Optional[float] = None, piezoviscosity: Optional[str] = None,
              roelands_index: Optional[float] = None, compressibility: Optional[str] = None,
              couette_scheme: Optional[str] = None, film_preconditioner: Optional[str] = None,
              fft_planning: Optional[str] = None, eyring_stress: Optional[float] = None,
              limiting_shear_stress: Optional[float] = None,
              limiting_shear_slope: Optional[float] = None, mixed: bool = False, offset: Optional[float] = None,
              contact_friction: Optional[float] = None, boundary_film: Optional[float] = None,
              time_step: Optional[float] = None, steps: Optional[int] = None, time_scheme: Optional[str] = None,
              approach_velocity: Optional[float] = None, separation_history: Optional[Sequence[float]] = None,
              threads: Optional[int] = None, trace: Optional[Union[str, "os.PathLike[str]"]] = None,
              speeds=None) -> tuple:
    height_map = _surface(surface, dx, dy)
    # The rules are the library's (make_lubrication_problem); here the
    # keywords only become its options (lubrication_option_names).
    if entrainment_velocity is None:
        raise _core.InputError("entrainment_velocity= is needed: UX or (UX, UY) in m/s")
    numbers = {name: _optional_float(value, name) for name, value in (
        ("separation", separation), ("force", force), ("e_star", e_star), ("E1", E1), ("nu1", nu1), ("E2", E2),
        ("nu2", nu2), ("pressure_viscosity", pressure_viscosity), ("roelands_index", roelands_index),
        ("eyring_stress", eyring_stress), ("limiting_shear_stress", limiting_shear_stress),
        ("limiting_shear_slope", limiting_shear_slope), ("offset", offset), ("contact_friction", contact_friction),
        ("boundary_film", boundary_film), ("time_step", time_step), ("approach_velocity", approach_velocity))}
    film = {
        **numbers, **_coating(coating), "viscosity": float(viscosity),
        "entrainment_velocity": _velocity(entrainment_velocity, "entrainment_velocity"),
        "sliding_velocity": None if sliding_velocity is None else _velocity(sliding_velocity, "sliding_velocity"),
        "inlet_pressure": float(inlet_pressure), "outlet_pressure": float(outlet_pressure),
        "side_pressure": float(side_pressure), "periodic_x": bool(periodic_x), "periodic_y": bool(periodic_y),
        "supply_fluid_fraction": float(supply_fluid_fraction), "tolerance": _optional_float(tol, "tol"),
        "max_iterations": None if max_iter is None else int(max_iter), "boundary": boundary,
        "piezoviscosity": piezoviscosity, "compressibility": compressibility, "couette_scheme": couette_scheme,
        "film_preconditioner": film_preconditioner, "fft_planning": fft_planning, "mixed": bool(mixed),
        "speeds": _sequence(speeds, "speeds must be a sequence of entrainment speeds (m/s)"),
        "steps": None if steps is None else int(steps), "time_scheme": time_scheme,
        "separation_history": _sequence(separation_history,
                                        "separation_history must be a sequence of separations (m), one a step")}
    return (height_map.heights, height_map.dx, height_map.dy or 0.0, film, None if threads is None else int(threads),
            None if trace is None else os.fspath(trace))


def _called(name: str, surface, keywords: dict, speeds=None, **fixed) -> tuple:
    """_arguments for the public function `name`: a wrong keyword's TypeError names `name`."""
    if "speeds" in keywords:
        raise TypeError(f"{name}() got an unexpected keyword argument 'speeds'")
    try:
        return _arguments(surface, speeds=speeds, **fixed, **keywords)
    except TypeError as error:
        raise TypeError(str(error).replace("_arguments()", f"{name}()")) from None


def lubricate(surface: Union[HeightMap, np.ndarray], **keywords: Any) -> Union[Film, FilmHistory]:
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
        couette_scheme ("first-order", "second-order"); film_preconditioner
        (the GMRES preconditioner: "multigrid", the default, or "sparse-lu",
        exact, for cross-checks); fft_planning (FFTW's effort planning the
        elastic film's transforms: "estimate", the default, "measure" or
        "patient").
    eyring_stress (tau0, Pa), limiting_shear_stress (tau_L0, Pa),
        limiting_shear_slope (gamma): the film's Couette shear stress is
        tau0 asinh(tau_N / tau0) (Eyring) and/or at most tau_L0 + gamma p;
        the pressure and film stay the Newtonian solution.

    mixed: the elastic film may close (``--mixed``; a homogeneous body,
        e_star or E1, nu1, E2, nu2; profiles solved densely up to 2048 points,
        longer profiles and 2D maps by Newton-GMRES, docs/solvers.md): where
        the gap would be negative the asperities carry a contact pressure
        beside the fluid's. Its load is force= or, separation controlled,
        offset= (h0 of h = h0 + gap + K p, m); contact_friction (Coulomb mu
        on contact cells; None: 0.1), boundary_film (the thinnest film the
        Reynolds equation sees, m; None: 1e-9); tol, max_iter (None: 1e-8,
        200 Newton steps). A rough line contact is the smooth profile's
        heights plus the roughness's (as ``--roughness`` adds them).
    time_step: steps the rigid film in time (s; ``--time-step``): the
        transient Reynolds equation with the squeeze term d(h theta)/dt,
        from the steady film at separation= (t = 0), the separation moved
        by exactly one of approach_velocity (m/s, the separation falls as
        separation - V t; negative: the surfaces part), separation_history
        (the separation at the end of each step, m) or force (each step's
        separation carries it, the body's inertia neglected); steps (None
        with a history: its length); time_scheme ("bdf2", the default, or
        "backward-euler"). Returns a :class:`FilmHistory`.
    trace: a mixed film's trace (``--trace``): a CSV file that gets one
        line per Newton solve as it ends (grid, speed, steps, GMRES
        iterations, seconds; docs/file-format.md), written as the solve goes.
    threads: threads of an elastic or mixed film's solve (None: the CPUs
        this process may use, as the program). Process-wide, as in
        :func:`solve`.

    Returns a :class:`Film`. Non-convergence is not an exception (see
    ``Film.converged`` and ``.message``); bad options raise InputError naming
    the keyword, its value and the rule. The GIL is released while solving.
    """
    result = _core.lubricate(*_called("lubricate", surface, keywords))
    return FilmHistory(result) if keywords.get("time_step") is not None else Film(result)


# lubricate's keywords are _arguments' (one list): help() and inspect show them.
lubricate.__signature__ = inspect.signature(_arguments).replace(
    parameters=[p for p in inspect.signature(_arguments).parameters.values() if p.name != "speeds"],
    return_annotation=Union[Film, FilmHistory])


def stribeck(surface: Union[HeightMap, np.ndarray], speeds: Sequence[float], **keywords: Any) -> StribeckCurve:
    """The mixed film's Stribeck curve, as ``halfspace lubricate --mixed
    --speeds U1,U2,... --stribeck FILE.csv``.

    speeds: entrainment speeds (m/s, > 0), solved in the given order, each
        film starting from the previous one (a sweep from fast to slow
        follows the film into contact). The velocities are those of
        entrainment_velocity and sliding_velocity scaled to each speed
        (their directions and the slide-to-roll ratio kept).
    keywords: those of :func:`lubricate` for a mixed film (mixed=True is
        implied; load controlled: force=).

    Returns a :class:`StribeckCurve`. Bad keywords raise InputError (a value)
    or TypeError (an unknown keyword), naming it."""
    if "mixed" in keywords:
        raise TypeError("stribeck() takes no keyword 'mixed': the Stribeck curve is the mixed film's")
    return StribeckCurve(_core.lubricate(*_called("stribeck", surface, keywords, speeds=speeds, mixed=True)))
