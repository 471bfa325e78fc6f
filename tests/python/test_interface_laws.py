"""The interface laws from Python: the hardness cap and adhesion keywords
reach the library's SolverOptions (docs/python.md), and their results carry
the law's record."""

import math

import numpy as np
import pytest

import halfspace as hs

E_STAR = 1e9  # Pa


def test_hardness_caps_a_hertz_sphere():
    radius, force = 0.01, 0.2  # m, N
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * force / (2 * math.pi * a * a)
    hardness = 0.7 * p0
    surface = hs.generate.sphere(grid=(96, 96), size=1e-3, radius=radius)
    result = hs.solve(surface, e_star=E_STAR, force=force, hardness=hardness, fft_planning="estimate", threads=1)
    assert result.converged, result.message
    assert result.hardness == hardness
    # The cap holds to the solver's projection (exact), the load to round-off.
    assert result.max_pressure <= hardness * (1 + 1e-12)
    assert result.total_force == pytest.approx(force, rel=1e-9)
    # A core of cells at the cap, inside the (wider than Hertz) contact.
    at_cap = np.count_nonzero(result.pressure >= hardness * (1 - 1e-12))
    assert result.plastic_fraction == pytest.approx(at_cap / result.pressure.size, abs=1e-12)
    assert 0 < at_cap < np.count_nonzero(result.contact)
    elastic = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1)
    assert elastic.hardness is None and elastic.plastic_fraction == 0.0
    assert result.contact_fraction > elastic.contact_fraction


def test_maugis_dugdale_holds_a_flat_surface_apart_at_the_dugdale_stress():
    # A flat periodic surface at a gap within the range h0: the attraction is
    # sigma0 = w / h0 on every cell, so the mean pressure is -sigma0.
    work, h0 = 0.05, 2e-8  # J/m^2, m
    flat = np.zeros((32, 32))
    result = hs.solve(flat, dx=1e-6, e_star=E_STAR, boundary="periodic", approach=-h0 / 2, adhesion="md",
                      work_of_adhesion=work, adhesion_range=h0, fft_planning="estimate", threads=1)
    assert result.converged, result.message
    assert result.mean_pressure == pytest.approx(-work / h0, rel=1e-5)
    record = result.adhesion
    assert record["law"] == "md"
    assert record["work_of_adhesion"] == work and record["range"] == h0
    assert record["interaction_fraction"] == pytest.approx(1.0)
    assert record["adhesive_force"] < 0


def test_adhesion_keywords_are_checked():
    flat = np.zeros(64)
    with pytest.raises(hs.InputError, match="need adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, work_of_adhesion=0.05)
    with pytest.raises(hs.InputError, match="work_of_adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, adhesion="md", adhesion_range=1e-8)
    with pytest.raises(hs.InputError, match="adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, adhesion="sticky", work_of_adhesion=0.05,
                 adhesion_range=1e-8)
    with pytest.raises(hs.InputError, match="hardness"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, force=1.0, hardness=-1.0)
