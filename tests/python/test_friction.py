"""Friction from Python (docs/python.md#friction): a Cattaneo-Mindlin sphere
against the analytic stick radius and tangential displacement, a fretting
history whose dissipated energy matches Mindlin-Deresiewicz, the fields as
views, saving as the program does, and the refusals naming the keyword."""

import csv
import math

import h5py
import numpy as np
import pytest

import halfspace as hs

E, NU = 2.1e11, 0.3          # steel on steel: similar bodies
RADIUS, FORCE, MU = 0.01, 10.0, 0.3
E_STAR = E / (2 * (1 - NU * NU))
A = (3 * FORCE * RADIUS / (4 * E_STAR)) ** (1 / 3)
G = E / (2 * (1 + NU))
# Cattaneo-Mindlin's displacement scale 3 mu P/(16 a) (2 (2 - nu)/G), both bodies (Johnson 1985, eq. 7.42).
DELTA_SCALE = 3 * MU * FORCE / (16 * A) * 2 * (2 - NU) / G
STEEL = dict(E1=E, nu1=NU, E2=E, nu2=NU)


def sphere(n):
    return hs.generate.sphere(grid=(n, n), size=2.4 * A, radius=RADIUS)


def test_cattaneo_mindlin_sphere():
    ratio = 0.5
    surface = sphere(40)
    result = hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_force=(ratio * MU * FORCE, 0.0),
                      threads=1, fft_planning="estimate")
    assert result.converged and result.friction["converged"], result.friction["message"]
    for name in ("shear_x", "shear_y", "slip_x", "slip_y", "tangential_displacement_x", "tangential_displacement_y"):
        field = getattr(result, name)
        assert field.shape == (40, 40) and field.dtype == np.float64
        assert not field.flags.owndata  # a view of the result's own array
    stick = result.stick
    assert stick.dtype == np.bool_ and not np.any(stick & ~result.contact)
    cell = surface.dx * surface.dy
    assert result.shear_x.sum() * cell == pytest.approx(ratio * MU * FORCE, rel=1e-9)
    assert np.all(np.hypot(result.shear_x, result.shear_y) <= MU * result.pressure * (1 + 1e-12))
    # Stick radius c = a (1 - Q/(mu P))^(1/3), as the radius of the stick cells' disc: within one cell (a/dx = 17).
    c = math.sqrt(stick.sum() * cell / math.pi)
    assert abs(c - A * (1 - ratio) ** (1 / 3)) <= surface.dx
    # Tangential approach within 0.5% of Cattaneo-Mindlin's (the program's test measures 4e-4).
    delta = result.friction["tangential_approach"][0]
    assert delta == pytest.approx(DELTA_SCALE * (1 - (1 - ratio) ** (2 / 3)), rel=5e-3)
    # stick_fraction is over the contact cells.
    assert result.friction["stick_fraction"] == pytest.approx(stick.sum() / result.contact.sum())
    assert result.attributes["stick_fraction"] == result.friction["stick_fraction"]
    assert result.attributes["tangential_force_x"] == pytest.approx(ratio * MU * FORCE, rel=1e-9)


def test_active_set_phase_gives_the_same_step():
    # tangential_active_set (--tangential-active-set): the same traction and approach as the default solver.
    ratio = 0.5
    surface = sphere(24)
    results = [hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_force=(ratio * MU * FORCE, 0.0),
                        tangential_tol=1e-10, tangential_active_set=updates, threads=1, fft_planning="estimate")
               for updates in (None, 20)]
    for result in results:
        assert result.converged and result.friction["converged"], result.friction["message"]
    plain, active = results
    limit = MU * plain.pressure.max()
    assert np.max(np.abs(active.shear_x - plain.shear_x)) <= 1e-3 * limit
    assert np.max(np.abs(active.shear_y - plain.shear_y)) <= 1e-3 * limit
    assert active.friction["tangential_approach"][0] == pytest.approx(plain.friction["tangential_approach"][0],
                                                                      rel=1e-4)
    assert active.friction["stick_fraction"] == pytest.approx(plain.friction["stick_fraction"], abs=0.01)


def test_coarse_start_gives_the_same_step():
    # tangential_coarse_start (--tangential-coarse-start): one coarser grid (32^2) starts the 64^2 step, which
    # converges to the fine start's traction and approach (both to a duality gap of 1e-10); None (automatic)
    # takes the coarse start on this grid.
    ratio = 0.5
    surface = sphere(64)
    results = [hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_force=(ratio * MU * FORCE, 0.0),
                        tangential_tol=1e-10, tangential_coarse_start=start, threads=1, fft_planning="estimate")
               for start in (False, True, None)]
    for result in results:
        assert result.converged and result.friction["converged"], result.friction["message"]
    plain, coarse, automatic = results
    assert plain.friction["coarse_levels"] == 0 and coarse.friction["coarse_levels"] == 1
    assert automatic.friction["coarse_levels"] == 1
    assert coarse.attributes["tangential_coarse_levels"] == 1
    limit = MU * plain.pressure.max()
    assert np.max(np.abs(coarse.shear_x - plain.shear_x)) <= 1e-4 * limit
    assert np.max(np.abs(coarse.shear_y - plain.shear_y)) <= 1e-4 * limit
    assert coarse.friction["tangential_approach"][0] == pytest.approx(plain.friction["tangential_approach"][0],
                                                                      rel=1e-6)


def test_fretting_history_dissipates_mindlin_deresiewicz_energy(tmp_path):
    amplitude = 0.6  # Q*/(mu P)
    peak = amplitude * MU * FORCE
    up = np.linspace(0, peak, 5)[1:]
    down = np.linspace(peak, -peak, 9)[1:]
    loads = list(up) + list(down) + list(-down)
    history = hs.history(sphere(32), **STEEL, force=FORCE, friction=MU, tangential_force=loads, threads=1,
                         fft_planning="estimate")
    assert history.converged and len(history) == len(loads)
    table = history.table
    assert table["Q_x"] == pytest.approx(loads, rel=1e-9, abs=1e-12)
    cycle = table["dissipated_energy"][len(up):].sum()
    x = amplitude
    loop = (9 * MU ** 2 * FORCE ** 2 / (10 * A) * 2 * (2 - NU) / G
            * (1 - (1 - x) ** (5 / 3) - 5 * x / 6 * (1 + (1 - x) ** (2 / 3))))
    # 8 steps a branch on a 32^2 grid (a/dx = 13): within 5% of
    # Mindlin-Deresiewicz (measured -0.85%; the steps' backward Euler
    # dissipation and the grid).
    assert cycle == pytest.approx(loop, rel=0.05)
    # Each step is a Result with that step's shear; the normal fields are shared.
    assert history[3].shear_x.sum() * history[3].dx ** 2 == pytest.approx(peak, rel=1e-9)
    assert history[-1].friction["step"] == len(loads) - 1
    assert history.normal.shear_x is None
    path = tmp_path / "loop.h5"
    history.save(path)
    with open(tmp_path / "loop.csv") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["dissipated_energy"]) for r in rows] == list(table["dissipated_energy"])
    with h5py.File(path) as f:
        assert f.attrs["history_steps"] == len(loads)
        assert f["steps/003/shear_x"].shape == (32, 32)
        np.testing.assert_array_equal(f["history/Q_x"][...], table["Q_x"])


def test_save_matches_the_program(tmp_path, cli):
    import subprocess
    q = 1.5
    surface = sphere(24)
    result = hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_force=q, threads=1,
                      fft_planning="estimate", solver="pk-fourier")
    result.save(tmp_path / "py.h5")
    subprocess.run([cli, "solve", "--geometry", "sphere", "--radius", str(RADIUS), "--grid", "24x24", "--size",
                    repr(2.4 * A), "--E1", repr(E), "--nu1", repr(NU), "--E2", repr(E), "--nu2", repr(NU),
                    "--force", repr(FORCE), "--friction", repr(MU), "--tangential-force", repr(q), "--threads", "1",
                    "--fft-planning", "estimate", "--solver", "pk-fourier", "--output", str(tmp_path / "cli.h5"),
                    "--quiet"], check=True)
    with h5py.File(tmp_path / "py.h5") as p, h5py.File(tmp_path / "cli.h5") as c:
        for name in ("shear_x", "shear_y", "stick", "slip_x", "tangential_displacement_x"):
            np.testing.assert_allclose(p[name][...], c[name][...], rtol=1e-9, atol=1e-9 * np.abs(c[name][...]).max())
        for name in ("friction_coefficient", "tangential_force_x", "tangential_approach_x", "stick_fraction"):
            assert p.attrs[name] == pytest.approx(c.attrs[name], rel=1e-9)


def test_sliding_and_displacement_control():
    surface = sphere(24)
    sliding = hs.solve(surface, **STEEL, force=FORCE, friction=MU, sliding=(1.0, 1.0), threads=1,
                       fft_planning="estimate")
    assert sliding.friction["gross_sliding"] and sliding.friction["stick_fraction"] == 0.0
    qx, qy = sliding.friction["tangential_force"]
    assert math.hypot(qx, qy) == pytest.approx(MU * FORCE, rel=1e-9) and qx == pytest.approx(qy)
    delta = DELTA_SCALE * (1 - 0.5 ** (2 / 3))
    moved = hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_displacement=delta, threads=1,
                     fft_planning="estimate")
    assert moved.friction["tangential_force"][0] == pytest.approx(0.5 * MU * FORCE, rel=0.03)


@pytest.mark.parametrize("keywords, message", [
    (dict(friction=-0.1, tangential_force=1.0), "friction=-0.1 is invalid"),
    (dict(tangential_force=1.0), "tangential_force=1,0 needs friction=MU"),
    (dict(friction=0.3), "needs a tangential load"),
    (dict(friction=0.3, tangential_force=1.0, sliding=(1, 0)), "cannot be combined"),
    (dict(friction=0.3, tangential_force=(1.0, 2.0, 3.0)), "use history() for several steps"),
    (dict(friction=0.3, tangential_force=4.0), "tangential_force=4,0 is invalid"),
    (dict(friction=0.3, tangential_force=1.0, tangential_max_iter=0), "tangential_max_iter=0 is invalid"),
    (dict(tangential_tol=1e-6), "tangential_tol=1e-06 needs friction=MU"),
    (dict(friction=0.3, tangential_force=1.0, tangential_release_period=0),
     "tangential_release_period=0 is invalid: must be at least 1"),
    (dict(tangential_release_period=2), "tangential_release_period=2 needs friction=MU"),
    (dict(friction=0.3, tangential_force=1.0, tangential_active_set=-1),
     "tangential_active_set=-1 is invalid: must be at least 0"),
    (dict(tangential_active_set=10), "tangential_active_set=10 needs friction=MU"),
    (dict(friction=0.3, tangential_force=1.0, tangential_coarse_start="on"),
     "tangential_coarse_start='on' is invalid: give True or False"),
    (dict(tangential_coarse_start=True), "tangential_coarse_start=on needs friction=MU"),
    (dict(friction=0.3, tangential_force=1.0, normal_load_steps=0), "normal_load_steps=0 is invalid"),
    (dict(friction=0.3, tangential_force=1.0, coupling="off"), "coupling='off' is invalid: give True or False"),
    (dict(friction=0.3, tangential_force=1.0, adhesion="md", work_of_adhesion=0.1, adhesion_range=1e-8),
     "adhesion=md cannot be combined with friction"),
])
def test_refusals_name_the_keyword(keywords, message):
    with pytest.raises(hs.InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        hs.solve(sphere(16), **STEEL, force=FORCE, threads=1, **keywords)


def test_a_step_that_does_not_converge_ends_the_history():
    history = hs.history(sphere(16), **STEEL, force=FORCE, friction=MU, tangential_force=[0.5, 1.0, 1.5],
                         tangential_max_iter=2, threads=1, fft_planning="estimate")
    assert not history.converged
    assert len(history) == 1 and not history[0].friction["converged"] and history[0].friction["iterations"] == 2


def test_dissimilar_bodies_are_solved_coupled():
    """A rigid body 2 (Dundurs' beta = 0.29): the normal and tangential problems solved together,
    the record says so; the load stays the one asked for."""
    r = hs.solve(sphere(16), E1=E, nu1=NU, E2=math.inf, nu2=NU, force=FORCE, friction=MU, tangential_force=1.0,
                 threads=1, fft_planning="estimate")
    assert r.friction["converged"] and r.friction["coupled"]
    assert r.friction["dundurs_beta"] == pytest.approx(0.4 / 1.4, rel=1e-12)
    assert r.friction["coupling_alternations"] >= 2


def test_coupling_off_keeps_the_frictionless_pressure():
    """coupling=False (the program's --no-coupling) on dissimilar bodies: the step is not coupled and
    its pressure is the frictionless solve's under the same load."""
    bodies = dict(E1=E, nu1=NU, E2=math.inf, nu2=NU)
    r = hs.solve(sphere(16), **bodies, force=FORCE, friction=MU, tangential_force=1.0, coupling=False,
                 threads=1, fft_planning="estimate")
    plain = hs.solve(sphere(16), **bodies, force=FORCE, threads=1, fft_planning="estimate")
    assert r.friction["converged"] and not r.friction["coupled"]
    np.testing.assert_allclose(r.pressure, plain.pressure, rtol=0, atol=1e-12 * np.max(plain.pressure))


def test_normal_load_steps_reach_the_load_asked_for():
    """normal_load_steps (the program's --normal-load-steps): the coupled normal load applied in
    increments still ends at the force asked for, converged."""
    history = hs.history(sphere(16), E1=E, nu1=NU, E2=math.inf, nu2=NU, force=FORCE, friction=MU,
                         tangential_force=[0.5], normal_load_steps=3, threads=1, fft_planning="estimate")
    assert history.converged and history[0].friction["coupled"]
    assert history[0].total_force == pytest.approx(FORCE, rel=1e-6)


def test_a_coupled_history_keeps_each_steps_pressure(tmp_path):
    """Dissimilar bodies (a rigid body 2): each step of a history has its own pressure, moved by its
    shear under the same load; history[k] shows it, and save() writes it into the step's group, equal
    to the one in memory."""
    history = hs.history(sphere(16), E1=E, nu1=NU, E2=math.inf, nu2=NU, force=FORCE, friction=MU,
                         tangential_force=[0.5, 2.0], threads=1, fft_planning="estimate")
    assert history.converged and history[1].friction["coupled"]
    p0, p1 = np.array(history[0].pressure), np.array(history[1].pressure)
    assert np.abs(p1 - p0).max() > 1e-4 * p1.max()
    assert history[1].total_force == pytest.approx(FORCE, rel=1e-6)
    assert history.normal.shear_x is None  # the normal loading's contact, before the first step
    history.save(tmp_path / "h.h5")
    with h5py.File(tmp_path / "h.h5") as f:
        np.testing.assert_array_equal(f["steps/000/pressure"][...], p0)
        np.testing.assert_array_equal(f["steps/001/pressure"][...], p1)
        assert f["steps/001"].attrs["total_force"] == history[1].total_force
        np.testing.assert_array_equal(f["pressure"][...], history.normal.pressure)


def test_material_refusals():
    surface = sphere(16)
    with pytest.raises(hs.InputError, match=r"friction=0.3 with e_star=.*: E\* only does not fix the tangential"):
        hs.solve(surface, e_star=E_STAR, force=FORCE, friction=MU, tangential_force=1.0)
    # A coating thick against the free domain (its tangential remainder goes in by DFT only below L/8).
    coated = (r"the coated half-space \(coating\['thickness'\].*\) cannot be combined with friction here: .*"
              r"free 16x16 grid needs a layer thin against the domain")
    with pytest.raises(hs.InputError, match=coated):
        hs.solve(surface, coating=dict(thickness=1e-2, layer_E=E, layer_nu=NU, substrate_E=E, substrate_nu=NU),
                 force=FORCE, friction=MU, tangential_force=1.0)


def test_coated_half_space_on_a_periodic_grid():
    """A coating whose layer is the substrate's material gives the homogeneous body's shear and
    approach (a rigid body 2); its stresses under the shear are the coated body's (body 1, under
    -q), which for this layer are the homogeneous body's under -q."""
    surface = sphere(24)
    coating = dict(thickness=2e-5, layer_E=E, layer_nu=NU, substrate_E=E, substrate_nu=NU)
    coated = hs.solve(surface, coating=coating, boundary="periodic", force=FORCE, friction=MU,
                      tangential_force=1.0, threads=1, fft_planning="estimate")
    plain = hs.solve(surface, E1=E, nu1=NU, E2=math.inf, nu2=NU, boundary="periodic", force=FORCE, friction=MU,
                     tangential_force=1.0, threads=1, fft_planning="estimate")
    assert coated.converged and coated.friction["converged"], coated.friction["message"]
    assert coated.coating is not None
    scale = MU * np.abs(np.array(plain.pressure)).max()
    np.testing.assert_allclose(coated.shear_x, plain.shear_x, rtol=0, atol=1e-9 * scale)
    np.testing.assert_array_equal(coated.stick, plain.stick)
    assert coated.friction["tangential_approach"][0] == pytest.approx(plain.friction["tangential_approach"][0],
                                                                      rel=1e-9)


def test_coated_stresses_take_the_coated_bodys_shear_as_the_program_does(tmp_path, cli):
    """subsurface_stress on a coated friction result (periodic) gives the coated body's field
    under the traction on it, -q, as `halfspace stress` does on the saved result (to 1e-12 of the
    largest); near the surface sigma_xz is then +q_x where the contact slides."""
    import subprocess
    surface = sphere(24)
    coating = dict(thickness=2e-5, layer_E=2 * E, layer_nu=0.22, substrate_E=E, substrate_nu=NU)
    coated = hs.solve(surface, coating=coating, boundary="periodic", force=FORCE, friction=MU, sliding=(1.0, 0.0),
                      threads=1, fft_planning="estimate")
    assert coated.converged and coated.friction["converged"], coated.friction["message"]
    depths = [2e-6, 1e-5, 4e-5]
    stresses = hs.subsurface_stress(coated, depths)
    assert stresses["tractions"] == "pressure and shear"
    assert list(stresses["in_layer"]) == [True, True, False]
    coated.save(tmp_path / "c.h5")
    subprocess.run([cli, "stress", str(tmp_path / "c.h5"), "--depths", ",".join(repr(z) for z in depths),
                    "--output", str(tmp_path / "stress.h5"), "--threads", "1", "--quiet"], check=True)
    with h5py.File(tmp_path / "stress.h5") as f:
        for name in ("sigma_xx", "sigma_xz", "von_mises"):
            program = f["stress"][name][...]
            np.testing.assert_allclose(stresses[name], program, rtol=0, atol=1e-12 * np.abs(program).max())
    # The shear changes the field; its sign is the coated body's (sigma_xz follows +q_x).
    shallow = hs.subsurface_stress(coated, [1e-3 * surface.dx])["sigma_xz"][0]
    inside = np.array(coated.pressure) > 0.5 * np.array(coated.pressure).max()
    shear_x = np.array(coated.shear_x)
    assert np.abs(shallow[inside] - shear_x[inside]).max() < 0.1 * np.abs(shear_x).max()


def test_stresses_take_the_shear_as_the_program_does(tmp_path, cli):
    """subsurface_stress on a friction result applies its shear beside the pressure: the same
    field as `halfspace stress` on the saved result (to 1e-12 of the largest), and a larger
    von Mises maximum than the frictionless contact's."""
    import subprocess
    surface = sphere(24)
    depths = [2e-6, 1e-5, 4e-5]
    sliding = hs.solve(surface, **STEEL, force=FORCE, friction=MU, sliding=(1.0, 0.0), threads=1,
                       fft_planning="estimate")
    stresses = hs.subsurface_stress(sliding, depths, nu=NU)
    assert stresses["tractions"] == "pressure and shear"
    sliding.save(tmp_path / "s.h5")
    subprocess.run([cli, "stress", str(tmp_path / "s.h5"), "--depths", ",".join(repr(z) for z in depths), "--nu",
                    repr(NU), "--output", str(tmp_path / "stress.h5"), "--threads", "1", "--quiet"], check=True)
    with h5py.File(tmp_path / "stress.h5") as f:
        tractions = f["stress"].attrs["tractions"]
        assert (tractions.decode() if isinstance(tractions, bytes) else tractions) == "pressure and shear"
        for name in ("sigma_xx", "sigma_xz", "von_mises"):
            program = f["stress"][name][...]
            np.testing.assert_allclose(stresses[name], program, rtol=0, atol=1e-12 * np.abs(program).max())
    plain = hs.solve(surface, **STEEL, force=FORCE, threads=1, fft_planning="estimate")
    frictionless = hs.subsurface_stress(plain, depths, nu=NU)
    assert frictionless["tractions"] == "pressure"
    assert stresses["max_von_mises"] > 1.05 * frictionless["max_von_mises"]


def test_read_result_brings_the_friction_step_back(tmp_path):
    """A saved friction result read back has the same fields, friction attributes and
    stresses under shear as the result that was solved."""
    surface = sphere(24)
    solved = hs.solve(surface, **STEEL, force=FORCE, friction=MU, tangential_force=(1.0, 0.5), threads=1,
                      fft_planning="estimate")
    solved.save(tmp_path / "f.h5")
    read = hs.read_result(tmp_path / "f.h5")
    for name in ("shear_x", "shear_y", "slip_x", "slip_y", "tangential_displacement_x", "tangential_displacement_y",
                 "stick"):
        np.testing.assert_array_equal(getattr(read, name), getattr(solved, name))
    for key in ("friction_coefficient", "tangential_force", "tangential_approach", "stick_fraction", "slip_fraction",
                "dissipated_energy", "gross_sliding", "converged", "iterations"):
        assert read.friction[key] == solved.friction[key], key
    depths = [5e-6, 2e-5]
    np.testing.assert_array_equal(hs.subsurface_stress(read, depths, nu=NU)["von_mises"],
                                  hs.subsurface_stress(solved, depths, nu=NU)["von_mises"])
    plain = hs.solve(surface, **STEEL, force=FORCE, threads=1, fft_planning="estimate")
    plain.save(tmp_path / "n.h5")
    assert hs.read_result(tmp_path / "n.h5").shear_x is None


def test_stresses_of_either_body(tmp_path, cli):
    """On a rigid body 2 the stresses are body 1's by default: under -q and with nu1, as
    `halfspace stress` computes them from the saved file (which records both bodies);
    body=2 gives body 2's field under q; two elastic bodies of different ratios must be named."""
    import subprocess
    surface = sphere(24)
    depths = [2e-6, 1e-5]
    rigid = dict(E1=1e9, nu1=0.5, E2=math.inf, nu2=0.5)
    sliding = hs.solve(surface, **rigid, force=FORCE, friction=MU, sliding=(1.0, 0.0), threads=1,
                       fft_planning="estimate")
    body1 = hs.subsurface_stress(sliding, depths)
    body2 = hs.subsurface_stress(sliding, depths, body=2)
    assert body1["body"] == 1 and body2["body"] == 2
    # Near the surface sigma_xz is the traction on the body: -q for body 1, +q for body 2 (z into each).
    shallow1 = hs.subsurface_stress(sliding, [1e-3 * surface.dx])["sigma_xz"][0]
    shallow2 = hs.subsurface_stress(sliding, [1e-3 * surface.dx], body=2)["sigma_xz"][0]
    inside = sliding.pressure > 0.1 * sliding.pressure.max()
    q = sliding.shear_x
    assert np.abs(shallow1[inside] - q[inside]).max() < 0.1 * np.abs(q).max()
    assert np.abs(shallow2[inside] + q[inside]).max() < 0.1 * np.abs(q).max()
    sliding.save(tmp_path / "s.h5")
    with h5py.File(tmp_path / "s.h5") as f:
        assert f.attrs["body1_nu"] == 0.5 and math.isinf(f.attrs["body2_E"])
    subprocess.run([cli, "stress", str(tmp_path / "s.h5"), "--depths", ",".join(repr(z) for z in depths),
                    "--output", str(tmp_path / "stress.h5"), "--threads", "1", "--quiet"], check=True)
    with h5py.File(tmp_path / "stress.h5") as f:
        assert f["stress"].attrs["body"] == 1
        program = f["stress"]["sigma_xz"][...]
        np.testing.assert_allclose(body1["sigma_xz"], program, rtol=0, atol=1e-12 * np.abs(program).max())
    read = hs.read_result(tmp_path / "s.h5")
    np.testing.assert_array_equal(hs.subsurface_stress(read, depths)["sigma_xz"], body1["sigma_xz"])
    with pytest.raises(hs.InputError, match="body= 3 is invalid"):
        hs.subsurface_stress(sliding, depths, body=3)
    dissimilar = hs.solve(surface, E1=1e9, nu1=0.3, E2=2e9, nu2=0.25, force=FORCE, threads=1,
                          fft_planning="estimate")
    with pytest.raises(hs.InputError, match="pass body= 1 or 2, or nu= NU"):
        hs.subsurface_stress(dissimilar, depths)
    assert hs.subsurface_stress(dissimilar, depths, body=1)["body"] == 1
