"""halfspace.lubricate(mixed=True) and halfspace.stribeck: the program's
mixed film and Stribeck curve (`halfspace lubricate --mixed`, `--speeds`) on
the same rough line contact, to rounding; bad keywords named in the error."""

import csv
import subprocess

import h5py
import numpy as np
import pytest

import halfspace as hs

# The rough line contact of tests/apps/lubricate_mixed_cli_test.cpp: a
# cylinder (R = 10 mm) with a self-affine roughness of 0.1 um rms, 97 points
# over 0.24 mm; a steel EHL line contact at 44 kN/m.
MIXED_FLAGS = ["--mixed", "--viscosity", "0.04", "--force", "4.4e4", "--E-star", "1.1e11", "--pressure-viscosity",
               "2.27e-8", "--piezoviscosity", "roelands", "--limiting-shear-slope", "0.05"]
MIXED = {"mixed": True, "viscosity": 0.04, "force": 4.4e4, "e_star": 1.1e11, "pressure_viscosity": 2.27e-8,
         "piezoviscosity": "roelands", "limiting_shear_slope": 0.05}

# The attributes the program writes for a mixed film and Film's names for them.
ATTRIBUTES = {"load": "load", "separation": "separation", "central_film_thickness": "central_film_thickness",
              "minimum_film_thickness": "minimum_film_thickness", "max_pressure": "max_pressure",
              "cavitated_fraction": "cavitated_fraction", "relative_residual": "relative_residual",
              "load_error": "load_error", "fluid_load": "fluid_load", "contact_load": "contact_load",
              "contact_load_fraction": "contact_load_fraction", "contact_area": "contact_area",
              "contact_area_fraction": "contact_area_fraction", "complementarity_error": "complementarity_error",
              "friction_coefficient": "friction_coefficient", "contact_friction": "contact_friction",
              "boundary_film": "boundary_film", "entrainment_speed": "entrainment_speed", "E_star": "e_star",
              "roelands_index": "roelands_index", "mean_pressure": "mean_pressure"}


@pytest.fixture
def rough_line(tmp_path, cli):
    """(cylinder file, roughness file, their heights summed, dx)."""
    directory = tmp_path
    for arguments, name in ((["--kind", "cylinder", "--radius", "0.01"], "cylinder.h5"),
                            (["--kind", "self-affine", "--rms-height", "1e-7", "--seed", "3"], "rough.h5")):
        subprocess.run([cli, "generate", *arguments, "--grid", "97", "--size", "2.4e-4", "--output",
                        str(directory / name), "--quiet"], check=True)
    cylinder = hs.read_height_map(directory / "cylinder.h5")
    rough = hs.read_height_map(directory / "rough.h5")
    return directory / "cylinder.h5", directory / "rough.h5", cylinder.heights + rough.heights, cylinder.dx


def _cli(cli, rough_line, output, more):
    cylinder, rough, _, _ = rough_line
    subprocess.run([cli, "lubricate", "--height-map", str(cylinder), "--roughness", str(rough), *MIXED_FLAGS, *more,
                    "--output", str(output), "--quiet"], check=True)
    with h5py.File(output, "r") as file:
        fields = {name: file[name][()] for name in file if isinstance(file[name], h5py.Dataset)}
        return fields, dict(file.attrs)


def _assert_film_equals_file(mine, fields, attributes):
    model = attributes["model"]
    assert mine.model == "mixed" == (model.decode() if isinstance(model, bytes) else model)
    for name in ("fluid_pressure", "contact_pressure", "pressure", "film", "fluid_fraction", "deformation"):
        np.testing.assert_allclose(getattr(mine, name), fields[name], rtol=1e-12, atol=0, err_msg=name)
    for attribute, name in ATTRIBUTES.items():
        assert getattr(mine, name) == pytest.approx(float(attributes[attribute]), rel=1e-12, abs=0), name
    for axis, component in enumerate("xy"):
        for kind in ("fluid_friction_force", "contact_friction_force", "friction_force"):
            expected = float(attributes[f"{kind}_{component}"])
            assert getattr(mine, kind)[axis] == pytest.approx(expected, rel=1e-12, abs=0), kind
    assert mine.iterations == int(attributes["iterations"])
    assert mine.converged and int(attributes["converged"]) == 1


def test_mixed_film_equals_cli(tmp_path, cli, rough_line):
    """A mixed-regime film (slow, sliding): both pressures, the film and the
    numbers as the program's; the load shared between fluid and contact."""
    fields, attributes = _cli(cli, rough_line, tmp_path / "m.h5", [
        "--entrainment-velocity", "0.001", "--sliding-velocity", "0.0005", "--contact-friction", "0.12"])
    _, _, heights, dx = rough_line
    # A solve on one thread first: the thread count is process-wide, and the
    # film's FFTs must use the program's (threads=None), or their rounding differs.
    hs.solve(hs.generate.sphere(grid=(16, 16), size=1e-3, radius=0.01), e_star=1e9, mean_pressure=1e5,
             boundary="free", threads=1)
    mine = hs.lubricate(heights, dx=dx, entrainment_velocity=0.001, sliding_velocity=0.0005, contact_friction=0.12,
                        **MIXED)
    _assert_film_equals_file(mine, fields, attributes)
    assert 0.01 < mine.contact_load_fraction < 0.99
    assert mine.contact_load == pytest.approx(mine.contact_load_fraction * mine.load, rel=1e-12)
    np.testing.assert_array_equal(mine.pressure, mine.fluid_pressure + mine.contact_pressure)
    assert np.all(mine.film[mine.contact_pressure > 0.0] == 0.0)
    assert mine.shear_x is None and mine.couette_friction_force is None


def test_separation_controlled_mixed_film_equals_cli(tmp_path, cli, rough_line):
    """offset= (h0) instead of force=, as --offset."""
    cylinder, rough, heights, dx = rough_line
    flags = list(MIXED_FLAGS)
    flags[flags.index("--force"):flags.index("--force") + 2] = ["--offset", "-5e-7"]
    subprocess.run([cli, "lubricate", "--height-map", str(cylinder), "--roughness", str(rough), *flags,
                    "--entrainment-velocity", "0.001", "--output", str(tmp_path / "o.h5"), "--quiet"], check=True)
    with h5py.File(tmp_path / "o.h5", "r") as file:
        fields = {name: file[name][()] for name in file if isinstance(file[name], h5py.Dataset)}
        attributes = dict(file.attrs)
    keywords = {**MIXED, "force": None}
    mine = hs.lubricate(heights, dx=dx, entrainment_velocity=0.001, offset=-5e-7, **keywords)
    _assert_film_equals_file(mine, fields, attributes)
    assert mine.separation == -5e-7 and 0.5 < mine.contact_load_fraction < 0.99


def test_stribeck_curve_equals_cli(tmp_path, cli, rough_line):
    """The sweep from full film into contact: the program's CSV (printed to 9
    digits) and its last film (to rounding)."""
    fields, attributes = _cli(cli, rough_line, tmp_path / "last.h5", [
        "--entrainment-velocity", "1", "--sliding-velocity", "0.5", "--speeds", "1,0.001,0.0001", "--stribeck",
        str(tmp_path / "s.csv"), "--trace", str(tmp_path / "t_cli.csv")])
    _, _, heights, dx = rough_line
    curve = hs.stribeck(heights, [1.0, 0.001, 0.0001], dx=dx, entrainment_velocity=1.0, sliding_velocity=0.5,
                        trace=tmp_path / "t_py.csv", **{k: v for k, v in MIXED.items() if k != "mixed"})
    assert len(curve) == 3 and curve.converged
    # The traces: the same Newton solves, line by line, but for their times.
    traces = []
    for name in ("t_cli.csv", "t_py.csv"):
        with open(tmp_path / name, newline="") as file:
            traces.append([{k: v for k, v in row.items() if k != "wall_seconds"} for row in csv.DictReader(file)])
    assert traces[0] == traces[1] and len(traces[0]) >= 3
    assert sum(int(row["newton_steps"]) for row in traces[1]) == sum(curve.newton_steps)
    with open(tmp_path / "s.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    assert list(rows[0].keys()) == list(hs.StribeckCurve.COLUMNS)
    for name in hs.StribeckCurve.COLUMNS:
        column = [row[name] for row in rows]
        if name == "status":
            assert curve.status == column
        elif name == "newton_steps":
            np.testing.assert_array_equal(curve.newton_steps, [int(v) for v in column])
        else:
            np.testing.assert_allclose(curve.table[name], [float(v) for v in column], rtol=1e-8, atol=1e-300,
                                       err_msg=name)
    np.testing.assert_allclose(curve.hersey_number, 0.04 * curve.entrainment_speed / 4.4e4, rtol=1e-14)
    assert curve.contact_load_fraction[0] == 0.0 < curve.contact_load_fraction[1] < curve.contact_load_fraction[2]
    # The last film is the file's (film_solves: the program counts the sweep's speeds).
    last = curve.films[-1]
    attributes = {**attributes, "film_solves": 1}
    _assert_film_equals_file(last, fields, attributes)


ROUGH = 1e-8 * np.sin(np.linspace(0.0, 20.0, 65))
LINE = 0.5 * (np.linspace(-1.2e-4, 1.2e-4, 65)) ** 2 / 0.01
KEYWORDS = {"dx": 3.75e-6, "viscosity": 0.04, "entrainment_velocity": 0.1, "force": 1e4, "e_star": 1.1e11,
            "mixed": True}


@pytest.mark.parametrize("keywords, message", [
    ({"contact_friction": -1.0}, "contact_friction=-1 is invalid"),
    ({"boundary_film": 0.0}, "boundary_film=0 m is invalid"),
    ({"tol": 2.0}, "tol=2 is invalid"),
    ({"max_iter": 0}, "max_iter=0 is invalid"),
    ({"force": -1.0}, "force=-1 is invalid"),
    ({"force": None, "offset": float("inf")}, "offset=inf m is invalid"),
    ({"force": None, "separation": 1e-6}, "separation is the rigid film's"),
    ({"offset": 1e-7}, "give exactly one of force=N and offset=M"),
    ({"e_star": None}, "mixed=True needs an elastic body"),
    ({"coating": {"thickness": 1e-5, "layer_E": 1e11, "layer_nu": 0.3, "substrate_E": 2e11, "substrate_nu": 0.3},
      "e_star": None}, "coating is not supported by the mixed film"),
    ({"mixed": False, "contact_friction": 0.1}, "belong to the mixed film: add mixed=True"),
    ({"limiting_shear_slope": -1.0}, "limiting_shear_slope=-1 is invalid"),
    ({"threads": 0}, "threads=0: thread count 0 is invalid"),
])
def test_bad_mixed_keyword_is_named(keywords, message):
    with pytest.raises(hs.InputError, match=message):
        hs.lubricate(-(LINE + ROUGH), **{**KEYWORDS, **keywords})


def test_unconverged_mixed_film_says_what_to_try():
    """Two Newton steps per solve (max_iter=2) do not bring the mixed film to
    tol=1e-15 (the speed continuation's solves neither): the film is
    returned unconverged, its message gives the solver's reason and then
    what to try, named by the keywords with the settings in force
    (LubricationProblem::failure_hint). (max_iter=1 alone converges here:
    the continuation's warm-started one-step solves reach 1e-8.)"""
    film = hs.lubricate(-(LINE + ROUGH), **{**KEYWORDS, "max_iter": 2, "tol": 1e-15})
    assert not film.converged and film.status != "converged"
    reason, hint = film.message.split("; to try: ")
    assert "mixed film did not converge in 2 Newton steps" in reason
    for named in ("speeds from a faster speed", "a smaller force", "more max_iter (now 2)",
                  "looser tol (now 1e-15)"):
        assert named in hint, named
    # The same film given its steps converges: the hint is the failure's only.
    converged = hs.lubricate(-(LINE + ROUGH), **KEYWORDS)
    assert converged.converged and "to try" not in converged.message


@pytest.mark.parametrize("keywords, message", [
    ({"speeds": [1.0, -0.1]}, r"speeds=-0.1 m/s is invalid"),
    ({"speeds": []}, "speeds must be a sequence"),
    ({"force": None, "offset": -1e-7}, "Stribeck sweep .*is load controlled: pass force="),
    ({"entrainment_velocity": 0.0}, "nonzero entrainment velocity"),
])
def test_bad_stribeck_keyword_is_named(keywords, message):
    arguments = {**{k: v for k, v in KEYWORDS.items() if k != "mixed"}, "speeds": [0.1]}
    arguments.update(keywords)
    speeds = arguments.pop("speeds")
    with pytest.raises(hs.InputError, match=message):
        hs.stribeck(-(LINE + ROUGH), speeds, **arguments)


def test_trace_needs_the_mixed_film(tmp_path):
    keywords = {k: v for k, v in KEYWORDS.items() if k not in ("mixed", "e_star")}
    with pytest.raises(hs.InputError, match="needs mixed=True"):
        hs.lubricate(-(LINE + ROUGH), trace=tmp_path / "t.csv", **keywords)
    assert not (tmp_path / "t.csv").exists()


def test_stribeck_refuses_unknown_and_mixed_keywords():
    arguments = {k: v for k, v in KEYWORDS.items() if k != "mixed"}
    with pytest.raises(TypeError, match="stribeck.*viscosty"):
        hs.stribeck(-(LINE + ROUGH), [0.1], viscosty=0.1, **{k: v for k, v in arguments.items() if k != "viscosity"})
    with pytest.raises(TypeError, match="mixed"):
        hs.stribeck(-(LINE + ROUGH), [0.1], mixed=False, **arguments)
