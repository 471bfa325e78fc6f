"""The coated half-space from Python: the coating= keyword of solve and sweep
reaches the library's coated solve_surface, equals `halfspace solve` with the
five coating options bit for bit, and subsurface_stress takes a coated
result's own Poisson's ratios."""

import subprocess

import numpy as np
import pytest

import halfspace as hs

HARD_COATING = {"thickness": 2e-5, "layer_E": 4e11, "layer_nu": 0.22, "substrate_E": 2.1e11, "substrate_nu": 0.29}


def test_coating_of_the_substrates_material_solves_like_the_homogeneous_half_space():
    # The kernel differs from 2/(E* q) by rounding only (M = 1 + O(eps)), and
    # so do the iterates: 1e-8 relative, as the program's test.
    surface = hs.generate.sphere(grid=(48, 48), size=4e-4, radius=0.01)
    same = {"thickness": 2e-5, "layer_E": 2.1e11, "layer_nu": 0.29, "substrate_E": 2.1e11, "substrate_nu": 0.29}
    coated = hs.solve(surface, coating=same, force=1.0, fft_planning="estimate", threads=1)
    e_star = 2.1e11 / (1 - 0.29 ** 2)
    homogeneous = hs.solve(surface, e_star=e_star, force=1.0, fft_planning="estimate", threads=1)
    assert coated.converged and homogeneous.converged
    assert coated.e_star == pytest.approx(e_star, rel=1e-15)
    assert coated.coating == same and homogeneous.coating is None
    scale = homogeneous.max_pressure
    assert np.max(np.abs(coated.pressure - homogeneous.pressure)) < 1e-8 * scale


def test_coated_solve_equals_cli_and_its_stresses_equal_the_stress_command(tmp_path, cli):
    output = tmp_path / "cli.h5"
    options = ["--layer-thickness", "2e-05", "--layer-E", "4e11", "--layer-nu", "0.22", "--substrate-E", "2.1e11",
               "--substrate-nu", "0.29"]
    subprocess.run([cli, "solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "48x48", "--size", "4e-4",
                    "--boundary", "periodic", "--force", "1", "--threads", "1", "--fft-planning", "estimate",
                    *options, "--output", str(output), "--quiet"], check=True)
    from_cli = hs.read_result(output)
    assert from_cli.coating == HARD_COATING
    surface = hs.generate.sphere(grid=(48, 48), size=4e-4, radius=0.01)
    mine = hs.solve(surface, coating=HARD_COATING, boundary="periodic", force=1.0, fft_planning="estimate",
                    threads=1)
    assert mine.converged and from_cli.converged
    assert np.array_equal(mine.heights, from_cli.heights)
    for field in ("pressure", "gap", "displacement"):
        assert np.array_equal(getattr(mine, field), getattr(from_cli, field)), field
    assert mine.e_star == from_cli.e_star

    depths = [5e-6, 2e-5, 3e-5]
    field = hs.subsurface_stress(mine, depths)
    assert field["in_layer"] == [True, True, False]
    from_file = hs.subsurface_stress(from_cli, depths)
    for name in ("sigma_xx", "sigma_zz", "sigma_xz", "von_mises", "hydrostatic"):
        assert np.array_equal(field[name], from_file[name]), name
    # The stress command on the program's result reports the same maximum.
    printed = subprocess.run([cli, "stress", str(output), "--depths", "5e-6,2e-5,3e-5", "--output",
                              str(tmp_path / "stress.h5"), "--threads", "1"], check=True, capture_output=True,
                             text=True).stdout
    line = next(text for text in printed.splitlines() if "max von Mises" in text)
    assert float(line.split()[3]) == pytest.approx(field["max_von_mises"], rel=1e-5)
    with pytest.raises(hs.InputError, match="nu=0.3 is not used"):
        hs.subsurface_stress(mine, depths, nu=0.3)


def test_coating_keyword_is_checked():
    surface = np.zeros((16, 16))
    with pytest.raises(hs.InputError, match=r"coating\['substrate_nu'\] cannot be combined with e_star"):
        hs.solve(surface, dx=1e-6, e_star=1e9, coating=HARD_COATING, force=1.0)
    with pytest.raises(hs.InputError, match=r"missing coating\['substrate_nu'\]"):
        hs.solve(surface, dx=1e-6, coating={k: v for k, v in HARD_COATING.items() if k != "substrate_nu"},
                 force=1.0)
    with pytest.raises(hs.InputError, match=r"coating\['thickness'\]=-1 is invalid: must be positive \(m\)"):
        hs.solve(surface, dx=1e-6, coating={**HARD_COATING, "thickness": -1.0}, force=1.0)
    with pytest.raises(hs.InputError, match="coated half-space"):
        hs.solve(surface, dx=1e-6, coating=HARD_COATING, force=1.0, solver="lemke")
    # Free grids: stresses below a layer up to L/8 thick (L = 400 um here).
    free = hs.solve(hs.generate.sphere(grid=(16, 16), size=4e-4, radius=0.01), coating=HARD_COATING, force=0.1,
                    fft_planning="estimate", threads=1)
    assert hs.subsurface_stress(free, [1e-5, 3e-5])["in_layer"] == [True, False]
    thick = hs.solve(hs.generate.sphere(grid=(16, 16), size=4e-4, radius=0.01),
                     coating={**HARD_COATING, "thickness": 6e-5}, force=0.1, fft_planning="estimate", threads=1)
    with pytest.raises(hs.InputError, match="need a layer thickness t <= L/8"):
        hs.subsurface_stress(thick, [1e-6])
    steps = hs.sweep(hs.generate.sphere(grid=(16, 16), size=4e-4, radius=0.01), coating=HARD_COATING,
                     force=[0.05, 0.1], fft_planning="estimate", threads=1)
    assert steps[1].coating == HARD_COATING
    assert steps[1].total_force == pytest.approx(0.1, rel=1e-9)
