"""halfspace.lubricate: the program's film on the same case (same numbers to
rounding), the rigid inclined slider against its closed form
(docs/validation.md), and bad keywords named in the error."""

import math
import subprocess

import h5py
import numpy as np
import pytest

import halfspace as hs


def _generate_cylinder(cli, path, grid, size):
    subprocess.run([cli, "generate", "--kind", "cylinder", "--grid", str(grid), "--size", str(size), "--radius",
                    "0.01", "--output", str(path), "--quiet"], check=True)


def _cli_film(cli, output, arguments):
    subprocess.run([cli, "lubricate", *arguments, "--output", str(output), "--quiet"], check=True)
    with h5py.File(output, "r") as file:
        fields = {name: file[name][()] for name in file if isinstance(file[name], h5py.Dataset)}
        return fields, dict(file.attrs)


def _assert_same(mine, fields, attributes, names):
    for name in ("pressure", "film", "fluid_fraction", "shear_x", *([] if mine.deformation is None else
                                                                      ["deformation"])):
        np.testing.assert_allclose(getattr(mine, name), fields[name], rtol=1e-12, atol=0, err_msg=name)
    for name in names:
        assert getattr(mine, name) == pytest.approx(float(attributes[name]), rel=1e-12, abs=0), name
    assert mine.friction_force[0] == pytest.approx(float(attributes["friction_force_x"]), rel=1e-12)
    assert mine.iterations == int(attributes["iterations"])
    assert mine.converged and int(attributes["converged"]) == 1


def test_rigid_film_equals_cli(tmp_path, cli):
    """Load control with cavitation on a cylinder profile, sliding: the
    separation search, the film and its shear as the program's."""
    _generate_cylinder(cli, tmp_path / "cylinder.h5", 201, 8e-4)
    fields, attributes = _cli_film(cli, tmp_path / "film.h5", [
        "--height-map", str(tmp_path / "cylinder.h5"), "--viscosity", "0.1", "--entrainment-velocity", "1",
        "--sliding-velocity", "0.2", "--force", "4000"])
    surface = hs.read_height_map(tmp_path / "cylinder.h5")
    mine = hs.lubricate(surface, viscosity=0.1, entrainment_velocity=1.0, sliding_velocity=0.2, force=4000.0)
    assert mine.model == "rigid"
    _assert_same(mine, fields, attributes, ("load", "separation", "central_film_thickness", "minimum_film_thickness",
                                            "max_pressure", "cavitated_fraction", "inflow", "outflow",
                                            "friction_coefficient", "relative_residual"))
    assert mine.film_solves == int(attributes["film_solves"])
    assert mine.cavitated_fraction > 0.0
    assert mine.outflow == pytest.approx(mine.inflow, rel=1e-9)  # mass conservation


def test_elastic_film_equals_cli(tmp_path, cli):
    """EHL line contact (Roelands, Dowson-Higginson) sliding with a limiting
    shear stress: the Newton iteration, the film and the traction as the
    program's."""
    _generate_cylinder(cli, tmp_path / "cylinder.h5", 129, 7e-4)
    fields, attributes = _cli_film(cli, tmp_path / "ehl.h5", [
        "--height-map", str(tmp_path / "cylinder.h5"), "--viscosity", "0.04", "--entrainment-velocity", "0.55",
        "--sliding-velocity", "0.5", "--force", "4.4e4", "--E-star", "1.1e11", "--pressure-viscosity", "2e-8",
        "--piezoviscosity", "roelands", "--limiting-shear-stress", "2e6", "--limiting-shear-slope", "0.05"])
    surface = hs.read_height_map(tmp_path / "cylinder.h5")
    mine = hs.lubricate(surface, viscosity=0.04, entrainment_velocity=0.55, sliding_velocity=0.5, force=4.4e4,
                        e_star=1.1e11, pressure_viscosity=2e-8, piezoviscosity="roelands",
                        limiting_shear_stress=2e6, limiting_shear_slope=0.05)
    assert mine.model == "elastic" and mine.compressibility == "dowson-higginson"
    _assert_same(mine, fields, attributes, ("load", "separation", "central_film_thickness", "minimum_film_thickness",
                                            "max_pressure", "friction_coefficient", "relative_residual"))
    assert mine.couette_friction_force[0] == pytest.approx(float(attributes["couette_friction_force_x"]), rel=1e-12)
    assert mine.load == pytest.approx(4.4e4, rel=1e-7)
    assert mine.minimum_film_thickness < mine.central_film_thickness
    # The Couette stress is at most the cap tau_L0 + gamma p, and reaches it somewhere.
    length = surface.dx * (surface.shape[-1] - 1)
    assert 0.0 < mine.couette_friction_force[0] <= 2e6 * length + 0.05 * mine.load
    assert mine.limited_fraction > 0.0


def test_rigid_slider_matches_closed_form():
    """Inclined slider h = ho (1 + K (1 - x/L)), K = 1: pressure and load per
    length against p = 6 eta U L K X (1 - X) / (ho^2 (2 + K) (1 + K - K X)^2)
    and W' = 6 eta U L^2 / (ho^2 K^2) (ln(1 + K) - 2K / (2 + K)) (U the
    entrainment speed, eta U = eta (u1 + u2) / 2), and the Couette friction
    eta du L ln(1 + K) / (K ho); second order in the spacing (401 nodes)."""
    length, ho, k, eta, u, du = 0.01, 1e-5, 1.0, 0.1, 1.0, 0.5
    n = 401
    x = np.linspace(0.0, 1.0, n)
    heights = -ho * k * (1.0 - x)  # film = separation + max z - z
    film = hs.lubricate(heights, dx=length / (n - 1), viscosity=eta, entrainment_velocity=u, sliding_velocity=du,
                        separation=ho)
    assert film.converged
    np.testing.assert_allclose(film.film, ho * (1.0 + k * (1.0 - x)), rtol=1e-14)
    exact = 12 * eta * u * length / ho**2 * k * x * (1 - x) / ((2 + k) * (1 + k - k * x) ** 2)
    assert np.max(np.abs(film.pressure - exact)) < 1e-4 * exact.max()
    load = 12 * eta * u * length**2 / (ho**2 * k**2) * (math.log(1 + k) - 2 * k / (2 + k))
    assert film.load == pytest.approx(load, rel=1e-4)
    couette = eta * du * length * math.log(1 + k) / (k * ho)
    assert film.couette_friction_force[0] == pytest.approx(couette, rel=1e-5)
    assert film.friction_force[0] == pytest.approx(couette - k * ho * load / (2 * length), rel=1e-4)
    assert film.cavitated_fraction == 0.0
    assert film.deformation is None and film.inflow == pytest.approx(film.outflow, rel=1e-9)


def test_periodic_two_dimensional_film_equals_the_profile():
    """A 2D film uniform along a periodic y is the 1D film."""
    n = 101
    x = np.linspace(0.0, 1.0, n)
    profile = -1e-5 * (1.0 - x)
    line = hs.lubricate(profile, dx=1e-4, viscosity=0.1, entrainment_velocity=1.0, separation=1e-5)
    plane = hs.lubricate(np.tile(profile, (8, 1)), dx=1e-4, viscosity=0.1, entrainment_velocity=(1.0, 0.0),
                         separation=1e-5, periodic_y=True)
    assert plane.pressure.shape == (8, 101)
    np.testing.assert_allclose(plane.pressure, np.tile(line.pressure, (8, 1)), rtol=0, atol=1e-9 * line.max_pressure)


def test_coated_body():
    """An EHL line contact on a periodic coated body: a coating of the
    substrate's own material is the homogeneous body (the layered kernel
    reduces to E*'s), and a softer coating spreads the load (lower peak)."""
    cylinder = hs.generate.cylinder(grid=128, size=7e-4, radius=0.01)
    keywords = {"viscosity": 0.04, "entrainment_velocity": 0.55, "force": 4.4e4, "pressure_viscosity": 2e-8,
                "boundary": "periodic"}
    plain = hs.lubricate(cylinder, e_star=2.1e11 / (1 - 0.3**2), **keywords)
    same = hs.lubricate(cylinder, coating={"thickness": 2e-5, "layer_E": 2.1e11, "layer_nu": 0.3,
                                           "substrate_E": 2.1e11, "substrate_nu": 0.3}, **keywords)
    soft = hs.lubricate(cylinder, coating={"thickness": 2e-5, "layer_E": 7e10, "layer_nu": 0.3,
                                           "substrate_E": 2.1e11, "substrate_nu": 0.3}, **keywords)
    assert plain.converged and same.converged and soft.converged
    np.testing.assert_allclose(same.pressure, plain.pressure, rtol=0, atol=1e-9 * plain.max_pressure)
    assert same.e_star == pytest.approx(plain.e_star, rel=1e-15)
    assert soft.max_pressure < 0.9 * plain.max_pressure
    with pytest.raises(hs.InputError, match=r"incomplete coated half-space: missing coating\['layer_E'\]"):
        hs.lubricate(cylinder, coating={"thickness": 2e-5}, **keywords)
    with pytest.raises(hs.InputError, match=r"coating\['substrate_nu'\] cannot be combined with e_star"):
        hs.lubricate(cylinder, e_star=1e11, coating={"thickness": 2e-5, "layer_E": 7e10, "layer_nu": 0.3,
                                                     "substrate_E": 2.1e11, "substrate_nu": 0.3}, **keywords)


PROFILE = -1e-5 * (1.0 - np.linspace(0.0, 1.0, 41))
BASE = {"dx": 1e-4, "viscosity": 0.1, "entrainment_velocity": 1.0, "separation": 1e-5}
# The wedge touches at its outlet edge: its EHL film carries 1e3 N/m (at 3e3
# N/m and more the film closes there, below 1e-15 m: a mixed film's load).
ELASTIC = {"dx": 1e-5, "viscosity": 0.04, "entrainment_velocity": 1.0, "force": 1e3, "e_star": 1e11}


@pytest.mark.parametrize("keywords, message", [
    ({"viscosity": -1.0}, "viscosity=-1 Pa s is invalid"),
    ({"separation": -1e-6}, "separation=-1e-06 m is invalid"),
    ({"tol": 2.0}, "tol=2 is invalid"),
    ({"max_iter": 0}, "max_iter=0 is invalid"),
    ({"inlet_pressure": -1.0}, "inlet_pressure=-1 Pa is invalid"),
    ({"supply_fluid_fraction": 1.5}, "supply_fluid_fraction=1.5 is invalid"),
    ({"entrainment_velocity": (1.0, 2.0)}, r"entrainment_velocity=2 m/s \(y component\) is invalid on a 1D grid"),
    ({"sliding_velocity": math.inf}, r"sliding_velocity=inf m/s \(x component\)"),
    ({"eyring_stress": -1.0}, "eyring_stress=-1 Pa is invalid"),
    ({"limiting_shear_slope": -0.05}, "limiting_shear_slope=-0.05 is invalid"),
    ({"separation": None}, "give exactly one of separation=M and force=N"),
    ({"force": 1.0}, "give exactly one of separation=M and force=N"),
    ({"pressure_viscosity": 2e-8}, "need an elastic film"),
    ({"periodic_x": True}, "periodic along every axis"),
])
def test_bad_rigid_keyword_is_named(keywords, message):
    with pytest.raises(hs.InputError, match=message):
        hs.lubricate(PROFILE, **{**BASE, **keywords})


@pytest.mark.parametrize("keywords, message", [
    ({"force": -1.0}, "force=-1 is invalid"),
    ({"force": None, "separation": 1e-6}, "load controlled: pass force="),
    ({"tol": 0.0}, "tol=0 is invalid"),
    ({"piezoviscosity": "exponential"}, "piezoviscosity='exponential'.*barus, roelands"),
    ({"piezoviscosity": "barus"}, "pressure_viscosity=0 1/Pa is invalid for Barus"),
    ({"piezoviscosity": "roelands", "roelands_index": -1.0}, "roelands_index=-1 is invalid"),
    ({"compressibility": "tait"}, "compressibility='tait'"),
    ({"couette_scheme": "third-order"}, "couette_scheme='third-order'"),
    ({"film_preconditioner": "jacobi"}, "film_preconditioner='jacobi'"),
    ({"fft_planning": "exhaustive"}, "fft_planning='exhaustive'.*'estimate', 'measure'"),
    ({"boundary": "open"}, "boundary:"),
    ({"e_star": -1.0}, "E\\*|e_star|modulus"),
    ({"E1": 2e11}, "e_star cannot be combined with E1"),
    ({"e_star": None, "E1": 2e11, "nu1": 0.3}, "incomplete material: missing E2, nu2"),
])
def test_bad_elastic_keyword_is_named(keywords, message):
    with pytest.raises(hs.InputError, match=message):
        hs.lubricate(PROFILE, **{**ELASTIC, **keywords})


def test_both_bodies_make_the_composite_modulus():
    pair = hs.lubricate(PROFILE, **{**ELASTIC, "e_star": None, "E1": 2e11, "nu1": 0.3, "E2": 1e11, "nu2": 0.25})
    e_star = 1.0 / ((1 - 0.3**2) / 2e11 + (1 - 0.25**2) / 1e11)
    single = hs.lubricate(PROFILE, **{**ELASTIC, "e_star": e_star})
    assert pair.converged and single.converged, single.message
    assert pair.e_star == pytest.approx(e_star, rel=1e-14)
    np.testing.assert_allclose(pair.pressure, single.pressure, rtol=0, atol=1e-9 * single.max_pressure)


def test_unknown_keyword_is_refused():
    with pytest.raises(TypeError, match="viscosty"):
        hs.lubricate(PROFILE, viscosty=0.1, **{k: v for k, v in BASE.items() if k != "viscosity"})


def test_unconverged_elastic_film_says_what_to_try():
    """One Newton step (max_iter=1) does not converge the EHL film: the film
    is returned unconverged, its message gives the solver's reason and then
    what to try, named by the keywords (LubricationProblem::failure_hint)."""
    film = hs.lubricate(PROFILE, **{**ELASTIC, "max_iter": 1})
    assert not film.converged and film.status != "converged"
    reason, hint = film.message.split("; to try: ")
    assert reason
    for named in ("faster entrainment_velocity", "smaller force", "more max_iter (now 1)", "looser tol",
                  "film_preconditioner sparse-lu"):
        assert named in hint, named
