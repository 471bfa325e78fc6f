"""solve, sweep and read_result: the contact solve from Python."""

from __future__ import annotations

import os
from typing import Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._height_map import HeightMap

ProgressCallback = Callable[[int, float], Optional[bool]]

_LOADS = ("force", "mean_pressure", "approach")
_TANGENTIAL = ("tangential_force", "tangential_displacement")


def composite_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """E* (Pa) of two elastic bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2."""
    return _core.composite_modulus(E1, nu1, E2, nu2)


_COATING_KEYS = ("thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu")
# The names make_problem gives the coating's constants (halfspace/problem.hpp).
_LAYER_NAMES = ("layer_thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu")


def _coating(coating) -> dict:
    """The coating mapping's constants as the problem's layer_ and substrate_ keywords. The rules (all five given,
    no other material keyword, the ranges) are the library's problem builders'."""
    if coating is None:
        return {}
    if not isinstance(coating, Mapping):
        raise _core.InputError("coating must be a mapping with the keys " + ", ".join(_COATING_KEYS))
    unknown = [str(key) for key in coating if key not in _COATING_KEYS]
    if unknown:
        raise _core.InputError(f"coating: unknown {', '.join(unknown)}; the keys are {', '.join(_COATING_KEYS)} "
                               "(m, Pa, -, Pa, -)")
    return {_LAYER_NAMES[_COATING_KEYS.index(key)]: float(value) for key, value in coating.items()}


def _loads(force, mean_pressure, approach, plural: bool) -> dict:
    """The load keywords given, each as a list of values (the library checks that exactly one is)."""
    loads = {}
    for mode, value in (("force", force), ("mean_pressure", mean_pressure), ("approach", approach)):
        if value is None:
            continue
        values = np.atleast_1d(np.asarray(value, dtype=np.float64))
        if plural and (values.ndim != 1 or values.size == 0):
            raise _core.InputError(f"{mode} must be a non-empty sequence of values for a sweep")
        if not plural and np.ndim(value) != 0:
            raise _core.InputError(f"{mode} must be one number for solve(); use sweep() for several loads")
        loads[mode] = [float(v) for v in values]
    return loads


def _surface(surface, dx, dy) -> HeightMap:
    if isinstance(surface, HeightMap):
        if dx is not None or dy is not None:
            raise _core.InputError("dx and dy apply to arrays only: a HeightMap carries its own spacing")
        return surface
    if dx is None:
        raise _core.InputError("an array surface needs dx= (and dy= for a 2D map if it differs from dx), in m")
    return HeightMap(surface, dx, dy)


def _call_text(name: str, surface: HeightMap, keywords: dict) -> str:
    """The call as the result file's command_line records it."""
    shown = ", ".join(f"{key}={value!r}" for key, value in keywords.items() if value is not None)
    grid = "x".join(map(str, surface.shape[::-1]))
    return f"python: halfspace.{name}(<{grid} surface>, {shown})"


def _problem(e_star, E1, nu1, E2, nu2, coating, loads, solver, tol, max_iter, fft_planning, deflation_block, threads,
             laws) -> dict:
    """The problem's keywords that were given; _core's make_problem (halfspace/problem.hpp) holds their rules."""
    keywords = {"e_star": e_star, "E1": E1, "nu1": nu1, "E2": E2, "nu2": nu2, **_coating(coating),
                **loads, "solver": solver, "tol": tol, "max_iter": max_iter, "fft_planning": fft_planning,
                "deflation_block": deflation_block, "threads": threads, **laws}
    return {key: value for key, value in keywords.items() if value is not None}


def _shown(problem: dict, single: bool) -> dict:
    """The problem's keywords as the call shows them: a single solve's load as one number."""
    return {key: value[0] if single and key in _LOADS else value for key, value in problem.items()}


def _laws(hardness, adhesion, work_of_adhesion, adhesion_range, adhesion_stress, adhesion_tol,
          adhesion_precondition) -> dict:
    """The interface-law keywords that were given."""
    precondition = None if adhesion_precondition is None else ("on" if adhesion_precondition else "off")
    return {"hardness": hardness, "adhesion": adhesion, "work_of_adhesion": work_of_adhesion,
            "adhesion_range": adhesion_range, "adhesion_stress": adhesion_stress, "adhesion_tol": adhesion_tol,
            "adhesion_precondition": precondition}


def _with_active_set(keywords: dict, active_set: Optional[Union[bool, str]]) -> dict:
    """The problem keywords with pk-multilevel's active-set phase, when given."""
    if active_set is None:
        return keywords
    if active_set == "automatic":
        return {**keywords, "active_set": "automatic"}
    if not isinstance(active_set, bool):
        raise _core.InputError(f"active_set={active_set!r} is invalid: give True, False or \"automatic\"")
    return {**keywords, "active_set": "on" if active_set else "off"}


def solve(surface: Union[HeightMap, np.ndarray], *, dx: Optional[float] = None, dy: Optional[float] = None,
          e_star: Optional[float] = None, E1: Optional[float] = None, nu1: Optional[float] = None,
          E2: Optional[float] = None, nu2: Optional[float] = None, boundary: str = "free",
          force: Optional[float] = None, mean_pressure: Optional[float] = None, approach: Optional[float] = None,
          solver: Optional[str] = None, tol: float = 1e-10, max_iter: Optional[int] = None,
          threads: Optional[int] = None, initial_pressure: Optional[np.ndarray] = None,
          progress: Optional[ProgressCallback] = None, fft_planning: str = "measure",
          deflation_block: Optional[int] = None, hardness: Optional[float] = None,
          adhesion: Optional[str] = None, work_of_adhesion: Optional[float] = None,
          adhesion_range: Optional[float] = None, adhesion_stress: Optional[float] = None,
          adhesion_tol: Optional[float] = None, adhesion_precondition: Optional[bool] = None,
          coating: Optional[Mapping[str, float]] = None, friction: Optional[float] = None,
          tangential_force: Optional[Union[float, Sequence[float]]] = None,
          tangential_displacement: Optional[Union[float, Sequence[float]]] = None,
          sliding: Optional[Sequence[float]] = None, tangential_tol: Optional[float] = None,
          tangential_max_iter: Optional[int] = None, tangential_release_period: Optional[int] = None,
          tangential_active_set: Optional[int] = None, tangential_coarse_start: Optional[bool] = None,
          coupling: Optional[bool] = None, normal_load_steps: Optional[int] = None,
          active_set: Optional[Union[bool, str]] = None,
          precision: Optional[str] = None) -> _core.Result:
    """Solves the contact of a rigid rough surface on an elastic half-space, frictionless or with friction.

    surface: a HeightMap, or a 1D/2D array of heights (m, peaks positive,
        ``(ny, nx)``) with ``dx`` (and ``dy``) in m. float64 C-contiguous
        arrays are used in place; others are converted once.
    e_star: composite modulus E* (Pa), or E1, nu1, E2, nu2 of both bodies.
    boundary: "free" (an isolated patch) or "periodic" (the surface repeats).
    force / mean_pressure / approach: exactly one load: total force (N, N/m
        for a profile), mean pressure (Pa) or rigid-body approach (m).
    solver: "pk-multilevel" (None: the default), "pk-fourier", "pk", "lemke", "lcpquad".
    tol: relative residual at which the solve stops; max_iter: iteration
        limit (None: the library's 10000; lcpquad takes none).
    threads: threads of the solve (None: the CPUs this process may use). It
        is process-wide: it also sets the threads of later FFT plans.
    active_set: pk-multilevel begins its finest grid with primal-dual
        active-set steps: True (``--active-set on``), False, or "automatic"
        (None: the library's default, automatic: on for periodic grids from
        4096^2 cells on a homogeneous half-space, else off).
    initial_pressure: a warm start (Pa), shaped like the surface.
    progress: ``callable(iteration, residual)`` called after each iteration
        of the fine solve, on the calling thread; returning False stops the
        solve (status "stopped"), an exception it raises stops the solve and
        propagates.
    fft_planning: "estimate", "measure" (default, as the program) or
        "patient"; deflation_block: 0 turns the block-deflation correction
        off, B > 0 forces blocks of B x B cells (None: automatic).
    precision: "double" (None: the library's default, double) or "mixed"
        (``--precision``): the step's products and the preconditioner in
        single precision, the residual, contact decisions and convergence
        check in double; the Polonsky-Keer solvers on one process, not with
        adhesion (docs/solvers.md, "Mixed precision").
    hardness: a hardness cap H (Pa): 0 <= p <= H, cells at H flow
        plastically (``Result.plastic_fraction``); every solver but lemke,
        and the adhesive one (with ``adhesion``).
    adhesion: "md" (Maugis-Dugdale) or "exponential", with
        work_of_adhesion (J/m^2) and adhesion_range (h0 or rho, m) or, for
        md, adhesion_stress (sigma0, Pa). Adhesion has its own solver
        (adhesive-pcg) and tolerance, adhesion_tol (None: 1e-6); the
        approach may be negative. ``Result.adhesion`` holds its record.
        adhesion_precondition (None: True) chooses its minimiser:
        conjugate gradients preconditioned by the compliance
        (adhesive-pcg), or with False spectral projected gradients
        (adhesive-spg, 5-15x slower; docs/solvers.md).
    coating: a coated half-space instead of a homogeneous one: a mapping
        with ``thickness`` (m), ``layer_E`` (Pa), ``layer_nu``,
        ``substrate_E`` (Pa), ``substrate_nu``, as the program's
        ``--layer-thickness`` ... options; not combined with e_star or
        E1..nu2 (the indenter is rigid; ``Result.e_star`` is the layer's
        E1*). Solvers pk, pk-fourier, pk-multilevel; no adhesion; any grid
        (profiles too). ``Result.coating`` holds it.
    friction: Coulomb's coefficient mu (>= 0), with exactly one of
        tangential_force ``(QX, QY)`` or QX (N, N/m for a profile),
        tangential_displacement ``(DX, DY)`` or DX (m, the rigid tangential
        displacement of body 1 against body 2), or sliding ``(X, Y)`` (gross
        sliding along that direction: every contact cell at mu p). Needs E1,
        nu1, E2, nu2 (E2 may be ``inf``, a rigid body 2; dissimilar bodies
        are solved coupled) or a coating (periodic, or free 2D grids at
        least 8 split heights across; coupled unless coupling is off); no
        adhesion. The result then has the
        fields ``shear_x``, ``shear_y`` (Pa), ``stick`` (bool), ``slip_x``,
        ``slip_y`` (m), ``tangential_displacement_x``, ``_y`` (m) as views,
        and ``Result.friction`` the step's record; tangential_tol and
        tangential_max_iter are the tangential solver's tolerance and
        iteration limit (None: 1e-6 and 10000), tangential_release_period
        N releases slipping cells back to the stick set only every N
        iterations (``--tangential-release-period``; None: 5),
        tangential_active_set N runs at most N active-set (semi-smooth
        Newton) updates of the stick/slip sets before the conjugate
        gradients (``--tangential-active-set``; None: 0, none),
        tangential_coarse_start True solves each step first on grids of
        twice, four times, ... the spacing and starts from the prolonged
        traction (``--tangential-coarse-start on``; False: off; None:
        automatic, on wherever it applies). Dissimilar bodies: coupling
        False ignores the normal-tangential coupling (``--no-coupling``: the
        frictionless pressure; None: coupled), normal_load_steps N applies
        the normal load in N increments before the tangential steps
        (``--normal-load-steps``; None: 1). For several tangential loads in
        order use :func:`history`.

    The GIL is released while solving; Ctrl-C (KeyboardInterrupt) stops the
    solve within about 0.1 s. Non-convergence is not an exception: see
    ``Result.converged``, ``.status`` and ``.message``. Raises InputError for
    bad options, naming the keyword, its value and the rule.
    """
    friction_keywords = _friction_keywords(friction, tangential_force, tangential_displacement, sliding,
                                           tangential_tol, tangential_max_iter, tangential_release_period,
                                           tangential_active_set, tangential_coarse_start, coupling,
                                           normal_load_steps, plural=False)
    if friction_keywords:
        if initial_pressure is not None:
            raise _core.InputError("initial_pressure cannot be combined with friction")
        return _friction("solve", surface, dx, dy, e_star, E1, nu1, E2, nu2, boundary, force, mean_pressure,
                         approach, solver, tol, max_iter, threads, progress, fft_planning, deflation_block,
                         {**_with_active_set(_laws(hardness, adhesion, work_of_adhesion, adhesion_range,
                                                  adhesion_stress, adhesion_tol, adhesion_precondition), active_set),
                          "precision": precision},
                         coating, friction_keywords)[0]
    height_map = _surface(surface, dx, dy)
    start = None if initial_pressure is None else np.ascontiguousarray(initial_pressure, dtype=np.float64)
    problem = _problem(e_star, E1, nu1, E2, nu2, coating, _loads(force, mean_pressure, approach, plural=False), solver,
                       tol, max_iter, fft_planning, deflation_block, threads,
                       {**_with_active_set(_laws(hardness, adhesion, work_of_adhesion, adhesion_range,
                                                adhesion_stress, adhesion_tol, adhesion_precondition), active_set),
                        "precision": precision})
    call = _call_text("solve", height_map, {"boundary": boundary, **_shown(problem, single=True)})
    return _core.solve(height_map.heights, height_map.dx, height_map.dy or 0.0, boundary, problem, start, progress,
                       call, height_map.source, list(height_map.preparation))


def sweep(surface: Union[HeightMap, np.ndarray], *, dx: Optional[float] = None, dy: Optional[float] = None,
          e_star: Optional[float] = None, E1: Optional[float] = None, nu1: Optional[float] = None,
          E2: Optional[float] = None, nu2: Optional[float] = None, boundary: str = "free",
          force: Optional[Sequence[float]] = None, mean_pressure: Optional[Sequence[float]] = None,
          approach: Optional[Sequence[float]] = None, solver: Optional[str] = None, tol: float = 1e-10,
          max_iter: Optional[int] = None, threads: Optional[int] = None, warm_start: bool = True,
          progress: Optional[ProgressCallback] = None, fft_planning: str = "measure",
          deflation_block: Optional[int] = None, hardness: Optional[float] = None,
          adhesion: Optional[str] = None, work_of_adhesion: Optional[float] = None,
          adhesion_range: Optional[float] = None, adhesion_stress: Optional[float] = None,
          adhesion_tol: Optional[float] = None, adhesion_precondition: Optional[bool] = None,
          coating: Optional[Mapping[str, float]] = None, active_set: Optional[Union[bool, str]] = None,
          precision: Optional[str] = None) -> _core.Sweep:
    """Solves the surface under each load of a sequence, in order, each step
    warm-started from the previous one (as ``halfspace solve`` with several
    loads). Takes the keywords of :func:`solve`, with ``force``,
    ``mean_pressure`` or ``approach`` a sequence. Returns a Sweep: ``sweep[k]``
    is step k's Result, ``.table`` the summary columns as numpy arrays,
    ``.to_pandas()`` a DataFrame, ``.save(path)`` the program's HDF5 and CSV.
    A step that does not converge is kept with its status."""
    height_map = _surface(surface, dx, dy)
    problem = _problem(e_star, E1, nu1, E2, nu2, coating, _loads(force, mean_pressure, approach, plural=True), solver,
                       tol, max_iter, fft_planning, deflation_block, threads,
                       {**_with_active_set(_laws(hardness, adhesion, work_of_adhesion, adhesion_range,
                                                adhesion_stress, adhesion_tol, adhesion_precondition), active_set),
                        "precision": precision})
    call = _call_text("sweep", height_map, {"boundary": boundary, **_shown(problem, single=False),
                                            "warm_start": warm_start})
    return _core.sweep(height_map.heights, height_map.dx, height_map.dy or 0.0, boundary, problem, warm_start,
                       progress, call, height_map.source, list(height_map.preparation))


def _pair(value, name: str, plural: bool):
    """One tangential step (x, y) from a number or a pair."""
    array = np.asarray(value, dtype=np.float64)
    if array.ndim == 0:
        return [float(array), 0.0]
    if array.shape == (2,):
        return [float(array[0]), float(array[1])]
    raise _core.InputError(f"{name} must be a number X or a pair (X, Y)" +
                           (", or a sequence of them" if plural else "; use history() for several steps"))


def _friction_keywords(friction, tangential_force, tangential_displacement, sliding, tangential_tol,
                       tangential_max_iter, tangential_release_period, tangential_active_set,
                       tangential_coarse_start, coupling, normal_load_steps, plural: bool) -> dict:
    """The friction keywords that were given, a tangential load as steps [x, y], a sliding direction as a
    list, tangential_coarse_start and coupling as "on" or "off"; _core's make_problem (halfspace/problem.hpp)
    holds their rules."""
    switches = {"tangential_coarse_start": tangential_coarse_start, "coupling": coupling}
    for name, value in switches.items():
        if value is not None and not isinstance(value, bool):
            raise _core.InputError(f"{name}={value!r} is invalid: give True or False")
    keywords = {"friction": friction, "tangential_tol": tangential_tol, "tangential_max_iter": tangential_max_iter,
                "tangential_release_period": tangential_release_period,
                "tangential_active_set": tangential_active_set,
                **{name: "on" if value else "off" for name, value in switches.items() if value is not None},
                "normal_load_steps": normal_load_steps}
    for name, value in (("tangential_force", tangential_force), ("tangential_displacement", tangential_displacement)):
        if value is not None:
            many = plural and np.ndim(value) != 0
            keywords[name] = [_pair(step, name, plural) for step in value] if many else [_pair(value, name, plural)]
    if sliding is not None:
        keywords["sliding"] = [float(v) for v in np.asarray(sliding, dtype=np.float64).ravel()]
    return {key: value for key, value in keywords.items() if value is not None}


def _friction(name, surface, dx, dy, e_star, E1, nu1, E2, nu2, boundary, force, mean_pressure, approach, solver, tol,
              max_iter, threads, progress, fft_planning, deflation_block, laws, coating, friction):
    """The frictional solve behind solve(friction=...) and history(); `friction` the friction keywords given."""
    height_map = _surface(surface, dx, dy)
    problem = {**_problem(e_star, E1, nu1, E2, nu2, coating, _loads(force, mean_pressure, approach, plural=False),
                          solver, tol, max_iter, fft_planning, deflation_block, threads, laws), **friction}
    shown = {key: value[0] if key in _TANGENTIAL and len(value) == 1 else value
             for key, value in _shown(problem, single=True).items()}
    call = _call_text(name, height_map, {"boundary": boundary, **shown})
    return _core.friction(height_map.heights, height_map.dx, height_map.dy or 0.0, boundary, problem, progress, call,
                          height_map.source, list(height_map.preparation))


def history(surface: Union[HeightMap, np.ndarray], *, friction: float, dx: Optional[float] = None,
            dy: Optional[float] = None, E1: Optional[float] = None, nu1: Optional[float] = None,
            E2: Optional[float] = None, nu2: Optional[float] = None, e_star: Optional[float] = None,
            boundary: str = "free", force: Optional[float] = None, mean_pressure: Optional[float] = None,
            approach: Optional[float] = None,
            tangential_force: Optional[Sequence[Union[float, Sequence[float]]]] = None,
            tangential_displacement: Optional[Sequence[Union[float, Sequence[float]]]] = None,
            tangential_tol: Optional[float] = None, tangential_max_iter: Optional[int] = None,
            tangential_release_period: Optional[int] = None, tangential_active_set: Optional[int] = None,
            tangential_coarse_start: Optional[bool] = None, coupling: Optional[bool] = None, normal_load_steps: Optional[int] = None,
            solver: Optional[str] = None, tol: float = 1e-10,
            max_iter: Optional[int] = None, threads: Optional[int] = None,
            progress: Optional[ProgressCallback] = None, fft_planning: str = "measure",
            deflation_block: Optional[int] = None, hardness: Optional[float] = None,
            coating: Optional[Mapping[str, float]] = None) -> _core.History:
    """A tangential load history (friction), as ``halfspace solve --friction``
    with several tangential steps: the normal contact under one load, then
    each tangential load of the sequence in order, each step starting from
    the state the previous one left (fretting loops: load, unload, reverse).

    tangential_force / tangential_displacement: a sequence of steps, each a
    number (along x) or a pair (X, Y): N (N/m for a profile), or m. Takes
    the other keywords of :func:`solve` with friction. Returns a History:
    ``history[k]`` is step k's Result (the normal fields and step k's shear,
    stick and slip), ``.table`` the columns step, Q_x, Q_y, delta_x, delta_y,
    stick_fraction, dissipated_energy as numpy arrays, ``.save(path)`` the
    program's history file and CSV. A step that does not converge ends the
    history (see ``.converged``)."""
    friction_keywords = _friction_keywords(friction, tangential_force, tangential_displacement, None, tangential_tol,
                                           tangential_max_iter, tangential_release_period, tangential_active_set,
                                           tangential_coarse_start, coupling, normal_load_steps, plural=True)
    return _friction("history", surface, dx, dy, e_star, E1, nu1, E2, nu2, boundary, force, mean_pressure, approach,
                     solver, tol, max_iter, threads, progress, fft_planning, deflation_block,
                     _laws(hardness, None, None, None, None, None, None), coating, friction_keywords)


def read_result(path: Union[str, os.PathLike], step: Optional[int] = None) -> _core.Result:
    """Reads a result file written by ``halfspace solve`` or ``Result.save``.
    For a sweep file, ``step`` chooses the step (default: the last)."""
    return _core.read_result(os.fspath(path), -1 if step is None else int(step))


def subsurface_stress(
    result: _core.Result, depths: Sequence[float], nu: Optional[float] = None, body: Optional[int] = None
) -> dict:
    """The stress field below a solved contact, as ``halfspace stress``.

    result: a Result (its pressure and grid); depths: depths below the
    surface (m, > 0); body: whose stresses, 1 or 2 (default: the one that
    deforms, body 1 for a coated result or a rigid body 2, else body 2);
    nu: Poisson's ratio of that body (default: its own, when the result was
    solved with E1, nu1, E2, nu2; E* alone does not fix it). Periodic grids use the Fourier-space
    half-space solution, free grids Love's rectangle coefficients by DC-FFT
    (docs/theory.md, subsurface stresses). A coated result (solved with
    ``coating=``; periodic grids, or free 2D grids whose shorter side is at
    least 8 layer thicknesses) takes no nu: each depth uses its body's, the
    layer's for z <= thickness. A friction result (``friction=``) applies its
    shear tractions beside the pressure, as ``halfspace stress`` does: q on
    body 2, -q (the traction on it) on body 1 (a coated body is body 1;
    periodic grids).

    Returns a dict: ``depths``; ``sigma_xx``, ``sigma_yy``, ``sigma_zz``,
    ``sigma_xy``, ``sigma_xz``, ``sigma_yz``, ``von_mises``, ``max_shear``,
    ``hydrostatic`` (Pa, compression negative), each ``(nz, ny, nx)``
    (``(nz, n)`` for a profile) and owned by numpy without a copy;
    ``max_von_mises`` and its ``max_von_mises_position`` ``(x, y, z)`` in m;
    for a coated result ``in_layer``, one bool per depth; ``tractions``
    (``"pressure"`` or ``"pressure and shear"``); ``body`` (1 or 2). The GIL is
    released while computing."""
    return _core.subsurface_stress(
        result,
        [float(z) for z in depths],
        None if nu is None else float(nu),
        None if body is None else str(body),
    )
