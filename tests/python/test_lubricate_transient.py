"""halfspace.lubricate(time_step=...): the transient rigid film as the
program's (same numbers to rounding), the parallel-plate squeeze film
against its closed form (docs/validation.md), and bad keywords named."""

import subprocess

import h5py
import numpy as np
import pytest

import halfspace as hs


def test_transient_film_equals_cli(tmp_path, cli):
    """An oscillating separation on a cylinder profile with cavitation: every
    step's pressure, the history columns and the CSV as the program's."""
    subprocess.run([cli, "generate", "--kind", "cylinder", "--grid", "101", "--size", "6e-4", "--radius", "0.01",
                    "--output", str(tmp_path / "cylinder.h5"), "--quiet"], check=True)
    subprocess.run([cli, "lubricate", "--height-map", str(tmp_path / "cylinder.h5"), "--viscosity", "0.1",
                    "--entrainment-velocity", "1", "--separation", "1e-5", "--time-step", "1e-4",
                    "--separation-history", "9e-6,1.2e-5,1e-5", "--output", str(tmp_path / "t.h5"), "--quiet"],
                   check=True)
    surface = hs.read_height_map(tmp_path / "cylinder.h5")
    mine = hs.lubricate(surface, viscosity=0.1, entrainment_velocity=1.0, separation=1e-5, time_step=1e-4,
                        separation_history=[9e-6, 1.2e-5, 1e-5])
    assert isinstance(mine, hs.FilmHistory)
    assert mine.converged and mine.steps_done == 3 and len(mine) == 4
    assert mine.time_scheme == "bdf2"
    with h5py.File(tmp_path / "t.h5", "r") as file:
        for k, film in enumerate(mine.films):
            np.testing.assert_array_equal(film.pressure, file[f"steps/{k:03d}/pressure"][()])
        for name in ("time", "separation", "load", "fluid_volume", "inflow", "outflow"):
            np.testing.assert_array_equal(getattr(mine, name), file[f"history/{name}"][()], err_msg=name)
    csv = np.genfromtxt(tmp_path / "t.csv", delimiter=",", names=True)
    np.testing.assert_array_equal(csv["load"], mine.load)
    assert mine.cavitated_fraction.max() > 0.0


def test_parallel_plate_squeeze_matches_closed_form():
    """Plates of width B approaching at V: W' = eta V B^3 / h^3, the
    trapezoidal sum of the exact quadratic pressure (1 - (dx / B)^2)."""
    n, width, eta, v, h0 = 101, 0.01, 0.1, 1e-4, 1e-5
    dx = width / (n - 1)
    history = hs.lubricate(np.zeros(n), dx=dx, viscosity=eta, entrainment_velocity=0.0, separation=h0,
                           time_step=5e-3, steps=4, approach_velocity=v, time_scheme="backward-euler")
    h = h0 - v * history.time[1:]
    np.testing.assert_allclose(history.separation[1:], h, rtol=1e-12)
    expected = eta * v * width**3 / h**3 * (1.0 - (dx / width) ** 2)
    np.testing.assert_allclose(history.load[1:], expected, rtol=1e-8)


@pytest.mark.parametrize("keywords, message", [
    ({"time_step": 0.0, "steps": 2, "approach_velocity": 1e-4}, "time_step=0 s is invalid"),
    ({"time_step": 1e-3, "steps": 2}, "exactly one of approach_velocity"),
    ({"steps": 2, "approach_velocity": 1e-4}, "add time_step"),
    ({"time_step": 1e-3, "steps": 2, "approach_velocity": 1e-4, "time_scheme": "euler"}, "time_scheme='euler'"),
    ({"time_step": 1e-3, "separation_history": [1e-5, -1.0]}, "separation_history=-1 m is invalid"),
])
def test_bad_transient_keyword_is_named(keywords, message):
    with pytest.raises(hs.InputError, match=message):
        hs.lubricate(np.zeros(11), dx=1e-3, viscosity=0.1, entrainment_velocity=0.0, separation=1e-5, **keywords)
