"""Hertz point and line contact from Python against the analytic solutions
(Johnson 1985, ch. 4): the package must hand the library the surface, the
material and the load it was given."""

import math

import numpy as np
import pytest

import halfspace as hs

E_STAR = 1e9  # Pa


def test_point_contact_matches_hertz():
    radius, force = 0.01, 0.2  # m, N
    n, size = 128, 1e-3
    surface = hs.generate.sphere(grid=(n, n), size=size, radius=radius)
    result = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1)
    assert result.converged, result.message
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * force / (2 * math.pi * a * a)
    delta = a * a / radius
    # Contact area: a cell-counted circle of radius a/dx = 15 cells; its
    # edge is resolved to about a cell, 2 dx / a = 13 % of the area.
    area = result.contact.sum() * surface.dx * surface.dy
    assert area == pytest.approx(math.pi * a * a, rel=0.13)
    # Peak pressure and approach: discretisation error of a few per cent at 15 cells per radius.
    assert result.max_pressure == pytest.approx(p0, rel=0.03)
    assert result.approach == pytest.approx(delta, rel=0.03)
    assert result.total_force == pytest.approx(force, rel=1e-9)
    assert result.pressure.shape == (n, n)


def test_line_contact_matches_hertz():
    radius, line_load = 0.01, 1e3  # m, N/m
    surface = hs.generate.cylinder(grid=512, size=2e-3, radius=radius)
    result = hs.solve(surface, e_star=E_STAR, force=line_load, threads=1, fft_planning="estimate")
    assert result.converged, result.message
    b = math.sqrt(4 * line_load * radius / (math.pi * E_STAR))
    peak = 2 * line_load / (math.pi * b)
    x = (np.arange(512) - 255.5) * surface.dx
    hertz = peak * np.sqrt(np.clip(1 - (x / b) ** 2, 0, None))
    # b spans 73 cells: the pressure agrees to 2 % of the peak away from the edge's cell.
    assert np.max(np.abs(result.pressure - hertz)) / peak < 0.05
    assert result.max_pressure == pytest.approx(peak, rel=0.01)
    assert result.contact.sum() * surface.dx == pytest.approx(2 * b, rel=2 * surface.dx / b + 0.01)


def test_material_from_both_bodies():
    surface = hs.generate.sphere(grid=(32, 32), size=1e-3, radius=0.01)
    direct = hs.solve(surface, e_star=hs.composite_modulus(210e9, 0.3, 70e9, 0.33), force=0.1,
                      fft_planning="estimate", threads=1)
    bodies = hs.solve(surface, E1=210e9, nu1=0.3, E2=70e9, nu2=0.33, force=0.1, fft_planning="estimate", threads=1)
    assert np.array_equal(direct.pressure, bodies.pressure)
    assert bodies.e_star == pytest.approx(1 / ((1 - 0.09) / 210e9 + (1 - 0.33**2) / 70e9), rel=1e-14)


def test_active_set_phase_gives_the_default_solvers_pressure():
    # pk-multilevel with and without its active-set phase (--active-set on)
    # solve the same LCP: solved to tolerance 1e-12, the pressures agree far
    # inside the discretisation error (1e-7 of the peak allows for the
    # stopping tests, which differ between the two).
    radius, force = 0.01, 0.2  # m, N
    surface = hs.generate.sphere(grid=(128, 128), size=1e-3, radius=radius)
    plain = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1, tol=1e-12)
    phased = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1, tol=1e-12,
                      active_set=True)
    assert plain.converged and phased.converged, phased.message
    assert np.max(np.abs(phased.pressure - plain.pressure)) <= 1e-7 * plain.max_pressure
    # The default, automatic, runs the phase only from 4096^2 cells: here it
    # is the solve without it, bit for bit.
    for off in (False, "automatic"):
        without = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1, tol=1e-12,
                           active_set=off)
        assert np.array_equal(without.pressure, plain.pressure), off
    with pytest.raises(hs.InputError, match=r"active_set='yes' is invalid"):
        hs.solve(surface, e_star=E_STAR, force=force, active_set="yes")
