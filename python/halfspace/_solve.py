"""solve, sweep and read_result: the contact solve from Python."""

from __future__ import annotations

import os
from typing import Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._height_map import HeightMap

ProgressCallback = Callable[[int, float], None]

_LOADS = ("force", "mean_pressure", "approach")


def composite_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """E* (Pa) of two elastic bodies: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2."""
    return _core.composite_modulus(E1, nu1, E2, nu2)


def _material(e_star, E1, nu1, E2, nu2) -> float:
    constants = {"E1": E1, "nu1": nu1, "E2": E2, "nu2": nu2}
    given = [name for name, value in constants.items() if value is not None]
    if e_star is not None and given:
        raise _core.InputError(f"e_star cannot be combined with {', '.join(given)}: give either e_star or all of "
                               "E1, nu1, E2, nu2")
    if e_star is not None:
        return float(e_star)
    if not given:
        raise _core.InputError("no material given: pass e_star, or E1, nu1, E2 and nu2")
    if len(given) < 4:
        missing = [name for name in constants if constants[name] is None]
        raise _core.InputError(f"incomplete material: missing {', '.join(missing)} (give all of E1, nu1, E2, nu2, "
                               "or e_star)")
    return _core.composite_modulus(E1, nu1, E2, nu2)


_COATING_KEYS = ("thickness", "layer_E", "layer_nu", "substrate_E", "substrate_nu")


def _coating(coating, e_star, E1, nu1, E2, nu2) -> Optional[list]:
    """The five constants of a coated half-space, in _core's order, or None."""
    if coating is None:
        return None
    given = [name for name, value in {"e_star": e_star, "E1": E1, "nu1": nu1, "E2": E2, "nu2": nu2}.items()
             if value is not None]
    if given:
        raise _core.InputError(f"coating cannot be combined with {', '.join(given)}: a coated half-space takes its "
                               "moduli from the coating (the indenter is rigid)")
    if not isinstance(coating, Mapping):
        raise _core.InputError("coating must be a mapping with the keys " + ", ".join(_COATING_KEYS))
    missing = [key for key in _COATING_KEYS if key not in coating]
    unknown = [str(key) for key in coating if key not in _COATING_KEYS]
    if missing or unknown:
        raise _core.InputError(f"coating: missing {', '.join(missing) or 'nothing'}, unknown "
                               f"{', '.join(unknown) or 'nothing'}; the keys are {', '.join(_COATING_KEYS)} "
                               "(m, Pa, -, Pa, -)")
    return [float(coating[key]) for key in _COATING_KEYS]


def _load(force, mean_pressure, approach, plural: bool):
    values = {"force": force, "mean_pressure": mean_pressure, "approach": approach}
    given = [name for name, value in values.items() if value is not None]
    if not given:
        raise _core.InputError("no load given: pass one of force, mean_pressure, approach")
    if len(given) > 1:
        raise _core.InputError(f"{' and '.join(given)} cannot be combined: give exactly one of force, "
                               "mean_pressure, approach")
    mode = given[0]
    value = values[mode]
    if plural:
        loads = np.atleast_1d(np.asarray(value, dtype=np.float64))
        if loads.ndim != 1 or loads.size == 0:
            raise _core.InputError(f"{mode} must be a non-empty sequence of values for a sweep")
        return mode, [float(v) for v in loads]
    if np.ndim(value) != 0:
        raise _core.InputError(f"{mode} must be one number for solve(); use sweep() for several loads")
    return mode, float(value)


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


def _solver_options(solver, tol, max_iter, fft_planning, deflation_block, laws) -> dict:
    # Keys are the keywords; _core maps each onto SolverOptions (python/src/solve.cpp).
    return {"solver": solver, "tol": tol, "max_iter": max_iter, "fft_planning": fft_planning,
            "deflation_block": deflation_block, **laws}


def _laws(hardness, adhesion, work_of_adhesion, adhesion_range, adhesion_stress, adhesion_tol,
          adhesion_precondition) -> dict:
    """The interface-law keywords that were given."""
    given = {"hardness": hardness, "adhesion": adhesion, "work_of_adhesion": work_of_adhesion,
             "adhesion_range": adhesion_range, "adhesion_stress": adhesion_stress, "adhesion_tol": adhesion_tol,
             "adhesion_precondition": adhesion_precondition}
    return {key: value for key, value in given.items() if value is not None}


def solve(surface: Union[HeightMap, np.ndarray], *, dx: Optional[float] = None, dy: Optional[float] = None,
          e_star: Optional[float] = None, E1: Optional[float] = None, nu1: Optional[float] = None,
          E2: Optional[float] = None, nu2: Optional[float] = None, boundary: str = "free",
          force: Optional[float] = None, mean_pressure: Optional[float] = None, approach: Optional[float] = None,
          solver: str = "pk-multilevel", tol: float = 1e-10, max_iter: Optional[int] = None,
          threads: Optional[int] = None, initial_pressure: Optional[np.ndarray] = None,
          progress: Optional[ProgressCallback] = None, fft_planning: str = "measure",
          deflation_block: Optional[int] = None, hardness: Optional[float] = None,
          adhesion: Optional[str] = None, work_of_adhesion: Optional[float] = None,
          adhesion_range: Optional[float] = None, adhesion_stress: Optional[float] = None,
          adhesion_tol: Optional[float] = None, adhesion_precondition: Optional[bool] = None,
          coating: Optional[Mapping[str, float]] = None) -> _core.Result:
    """Solves the frictionless contact of a rigid rough surface on an elastic half-space.

    surface: a HeightMap, or a 1D/2D array of heights (m, peaks positive,
        ``(ny, nx)``) with ``dx`` (and ``dy``) in m. float64 C-contiguous
        arrays are used in place; others are converted once.
    e_star: composite modulus E* (Pa), or E1, nu1, E2, nu2 of both bodies.
    boundary: "free" (an isolated patch) or "periodic" (the surface repeats).
    force / mean_pressure / approach: exactly one load: total force (N, N/m
        for a profile), mean pressure (Pa) or rigid-body approach (m).
    solver: "pk-multilevel" (default), "pk-fourier", "pk", "lemke", "lcpquad".
    tol: relative residual at which the solve stops; max_iter: iteration
        limit (None: the library's 10000; lcpquad takes none).
    threads: threads of the solve (None: the CPUs this process may use). It
        is process-wide: it also sets the threads of later FFT plans.
    initial_pressure: a warm start (Pa), shaped like the surface.
    progress: ``callable(iteration, residual)`` called after each iteration
        of the fine solve, on the calling thread; an exception it raises
        stops the solve and propagates.
    fft_planning: "estimate", "measure" (default, as the program) or
        "patient"; deflation_block: 0 turns the block-deflation correction
        off, B > 0 forces blocks of B x B cells (None: automatic).
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

    The GIL is released while solving; Ctrl-C (KeyboardInterrupt) stops the
    solve within about 0.1 s. Non-convergence is not an exception: see
    ``Result.converged``, ``.status`` and ``.message``. Raises InputError for
    bad options, naming the keyword, its value and the rule.
    """
    height_map = _surface(surface, dx, dy)
    layers = _coating(coating, e_star, E1, nu1, E2, nu2)
    modulus = 0.0 if layers else _material(e_star, E1, nu1, E2, nu2)
    mode, value = _load(force, mean_pressure, approach, plural=False)
    start = None if initial_pressure is None else np.ascontiguousarray(initial_pressure, dtype=np.float64)
    options = _solver_options(solver, tol, max_iter, fft_planning, deflation_block,
                              _laws(hardness, adhesion, work_of_adhesion, adhesion_range, adhesion_stress,
                                    adhesion_tol, adhesion_precondition))
    material = {"coating": dict(zip(_COATING_KEYS, layers))} if layers else {"e_star": modulus}
    call = _call_text("solve", height_map, {**material, "boundary": boundary, mode: value, **options,
                                            "threads": threads})
    return _core.solve(height_map.heights, height_map.dx, height_map.dy or 0.0, boundary, modulus, layers, mode,
                       value, options, threads, start, progress, call, height_map.source,
                       list(height_map.preparation))


def sweep(surface: Union[HeightMap, np.ndarray], *, dx: Optional[float] = None, dy: Optional[float] = None,
          e_star: Optional[float] = None, E1: Optional[float] = None, nu1: Optional[float] = None,
          E2: Optional[float] = None, nu2: Optional[float] = None, boundary: str = "free",
          force: Optional[Sequence[float]] = None, mean_pressure: Optional[Sequence[float]] = None,
          approach: Optional[Sequence[float]] = None, solver: str = "pk-multilevel", tol: float = 1e-10,
          max_iter: Optional[int] = None, threads: Optional[int] = None, warm_start: bool = True,
          progress: Optional[ProgressCallback] = None, fft_planning: str = "measure",
          deflation_block: Optional[int] = None, hardness: Optional[float] = None,
          adhesion: Optional[str] = None, work_of_adhesion: Optional[float] = None,
          adhesion_range: Optional[float] = None, adhesion_stress: Optional[float] = None,
          adhesion_tol: Optional[float] = None, adhesion_precondition: Optional[bool] = None,
          coating: Optional[Mapping[str, float]] = None) -> _core.Sweep:
    """Solves the surface under each load of a sequence, in order, each step
    warm-started from the previous one (as ``halfspace solve`` with several
    loads). Takes the keywords of :func:`solve`, with ``force``,
    ``mean_pressure`` or ``approach`` a sequence. Returns a Sweep: ``sweep[k]``
    is step k's Result, ``.table`` the summary columns as numpy arrays,
    ``.to_pandas()`` a DataFrame, ``.save(path)`` the program's HDF5 and CSV.
    A step that does not converge is kept with its status."""
    height_map = _surface(surface, dx, dy)
    layers = _coating(coating, e_star, E1, nu1, E2, nu2)
    modulus = 0.0 if layers else _material(e_star, E1, nu1, E2, nu2)
    mode, values = _load(force, mean_pressure, approach, plural=True)
    options = _solver_options(solver, tol, max_iter, fft_planning, deflation_block,
                              _laws(hardness, adhesion, work_of_adhesion, adhesion_range, adhesion_stress,
                                    adhesion_tol, adhesion_precondition))
    material = {"coating": dict(zip(_COATING_KEYS, layers))} if layers else {"e_star": modulus}
    call = _call_text("sweep", height_map, {**material, "boundary": boundary, mode: values, **options,
                                            "threads": threads, "warm_start": warm_start})
    return _core.sweep(height_map.heights, height_map.dx, height_map.dy or 0.0, boundary, modulus, layers, mode,
                       values, options, threads, warm_start, progress, call, height_map.source,
                       list(height_map.preparation))


def read_result(path: Union[str, os.PathLike], step: Optional[int] = None) -> _core.Result:
    """Reads a result file written by ``halfspace solve`` or ``Result.save``.
    For a sweep file, ``step`` chooses the step (default: the last)."""
    return _core.read_result(os.fspath(path), -1 if step is None else int(step))


def subsurface_stress(result: _core.Result, depths: Sequence[float], nu: Optional[float] = None) -> dict:
    """The stress field below a solved contact, as ``halfspace stress``.

    result: a Result (its pressure and grid); depths: depths below the
    surface (m, > 0); nu: Poisson's ratio of the body whose stresses are
    wanted (E* alone does not fix it). Periodic grids use the Fourier-space
    half-space solution, free grids Love's rectangle coefficients by DC-FFT
    (docs/theory.md, subsurface stresses). A coated result (solved with
    ``coating=``; periodic grids, or free 2D grids whose shorter side is at
    least 8 layer thicknesses) takes no nu: each depth uses its body's, the
    layer's for z <= thickness.

    Returns a dict: ``depths``; ``sigma_xx``, ``sigma_yy``, ``sigma_zz``,
    ``sigma_xy``, ``sigma_xz``, ``sigma_yz``, ``von_mises``, ``max_shear``,
    ``hydrostatic`` (Pa, compression negative), each ``(nz, ny, nx)``
    (``(nz, n)`` for a profile) and owned by numpy without a copy;
    ``max_von_mises`` and its ``max_von_mises_position`` ``(x, y, z)`` in m;
    for a coated result ``in_layer``, one bool per depth. The GIL is
    released while computing."""
    return _core.subsurface_stress(result, [float(z) for z in depths], None if nu is None else float(nu))
