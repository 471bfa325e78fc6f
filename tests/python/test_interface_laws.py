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


def test_adhesion_parameters_keep_the_programs_ranges():
    # The ranges of halfspace solve (physical_ranges.hpp), given or derived:
    # a stress w / range of 1e306 Pa ended "converged" with a force of -inf,
    # and sigma0 = 1e300 Pa gave h0 = 5e-302 m (issue 32).
    flat = np.zeros(64)
    common = dict(dx=1e-6, e_star=E_STAR, approach=-1e-8, adhesion="md", fft_planning="estimate", threads=1)
    with pytest.raises(hs.InputError, match=r"^adhesion_range=1e-06 m is invalid with the work of adhesion "
                                            r"1e\+300 J/m\^2: the adhesive stress work / range = 1e\+306 Pa"):
        hs.solve(flat, work_of_adhesion=1e300, adhesion_range=1e-6, **common)
    with pytest.raises(hs.InputError, match=r"^adhesion_stress=1e\+300 Pa is invalid: allowed range is "
                                            r"\[1e-09, 1e\+13\] Pa"):
        hs.solve(flat, work_of_adhesion=0.05, adhesion_stress=1e300, **common)
    with pytest.raises(hs.InputError, match=r"^adhesion_stress=1e\+13 Pa is invalid with the work of adhesion "
                                            r"0.05 J/m\^2: the range h0 = work / stress = 5e-15 m"):
        hs.solve(flat, work_of_adhesion=0.05, adhesion_stress=1e13, **common)
    with pytest.raises(hs.InputError, match=r"^adhesion_range=1e-13 m is invalid: allowed range is"):
        hs.solve(flat, work_of_adhesion=0.05, adhesion_range=1e-13, **common)
    with pytest.raises(hs.InputError, match=r"^work_of_adhesion=-1 J/m\^2 is invalid"):
        hs.solve(flat, work_of_adhesion=-1.0, adhesion_range=1e-8, **common)


def test_adhesion_keywords_are_checked():
    flat = np.zeros(64)
    with pytest.raises(hs.InputError, match="work_of_adhesion needs adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, work_of_adhesion=0.05)
    with pytest.raises(hs.InputError, match="work_of_adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, adhesion="md", adhesion_range=1e-8)
    with pytest.raises(hs.InputError, match="adhesion"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, adhesion="sticky", work_of_adhesion=0.05,
                 adhesion_range=1e-8)
    with pytest.raises(hs.InputError, match="hardness"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, force=1.0, hardness=-1.0)


def test_subsurface_stress_on_the_axis_of_a_hertz_sphere():
    # Johnson (1985) eq. 3.45: sigma_z = -p0 / (1 + z^2/a^2) on the axis;
    # the maximum shear 0.31 p0 lies at z = 0.48 a for nu = 0.3.
    radius, force, n = 0.01, 0.2, 128
    surface = hs.generate.sphere(grid=(n, n), size=1e-3, radius=radius)
    result = hs.solve(surface, e_star=E_STAR, force=force, fft_planning="estimate", threads=1)
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    p0 = 3 * force / (2 * math.pi * a * a)
    depths = [0.25 * a, 0.48 * a, a]
    field = hs.subsurface_stress(result, depths, nu=0.3)
    assert field["sigma_zz"].shape == (3, n, n)
    centre = np.unravel_index(np.argmax(result.pressure), result.pressure.shape)
    for k, z in enumerate(depths):
        # 15 cells per contact radius: a few per cent of p0 from the discretised pressure.
        assert field["sigma_zz"][k][centre] == pytest.approx(-p0 / (1 + (z / a) ** 2), abs=0.03 * p0)
    assert field["max_shear"][1][centre] == pytest.approx(0.31 * p0, abs=0.02 * p0)
    assert field["max_von_mises"] == pytest.approx(np.max(field["von_mises"]))
    with pytest.raises(hs.InputError):
        hs.subsurface_stress(result, [-1e-6], nu=0.3)


def test_preconditioned_adhesive_solver_holds_the_dugdale_stress():
    # adhesion_precondition=True selects the conjugate-gradient adhesive
    # solver (adhesive-pcg); on a flat surface within the range it must give
    # the same closed form as SPG: every cell at -sigma0 = -w / h0.
    work, h0 = 0.05, 2e-8  # J/m^2, m
    flat = np.zeros((32, 32))
    common = dict(dx=1e-6, e_star=E_STAR, boundary="periodic", approach=-h0 / 2, adhesion="md",
                  work_of_adhesion=work, adhesion_range=h0, fft_planning="estimate", threads=1)
    result = hs.solve(flat, adhesion_precondition=True, **common)
    assert result.converged, result.message
    assert result.solver == "adhesive-pcg"
    assert result.mean_pressure == pytest.approx(-work / h0, rel=1e-5)
    assert hs.solve(flat, adhesion_precondition=False, **common).solver == "adhesive-spg"
    assert hs.solve(flat, **common).solver == "adhesive-pcg"  # the default
    with pytest.raises(hs.InputError, match="adhesion_precondition need"):
        hs.solve(flat, dx=1e-6, e_star=E_STAR, approach=0.0, adhesion_precondition=True)
