"""A solve from Python equals `halfspace solve` bit for bit on the same input
and options (same threads, estimate FFT planning): both run the library's
solve_surface on the same heights."""

import subprocess

import numpy as np
import pytest

import halfspace as hs


@pytest.mark.parametrize("solver, boundary", [("pk-multilevel", "periodic"), ("pk-fourier", "free")])
def test_python_solve_equals_cli(tmp_path, data_dir, cli, solver, boundary):
    height_map = data_dir / "di-5-crop-48x64.h5"
    output = tmp_path / "cli.h5"
    subprocess.run([cli, "solve", "--height-map", str(height_map), "--detrend", "plane", "--E-star", "1e9",
                    "--mean-pressure", "2e6", "--boundary", boundary, "--solver", solver, "--tol", "1e-11",
                    "--threads", "2", "--fft-planning", "estimate", "--output", str(output), "--quiet"], check=True)
    from_cli = hs.read_result(output)

    surface = hs.read_height_map(height_map, detrend="plane")
    mine = hs.solve(surface, e_star=1e9, mean_pressure=2e6, boundary=boundary, solver=solver, tol=1e-11,
                    threads=2, fft_planning="estimate")
    assert mine.converged and from_cli.converged
    assert np.array_equal(mine.heights, from_cli.heights)
    for field in ("pressure", "gap", "displacement", "contact"):
        assert np.array_equal(getattr(mine, field), getattr(from_cli, field)), field
    assert np.array_equal(mine.residual_history, from_cli.residual_history)
    for number in ("iterations", "residual", "approach", "total_force", "mean_pressure", "max_pressure",
                   "contact_fraction"):
        assert getattr(mine, number) == getattr(from_cli, number), number
    assert mine.statistics == from_cli.statistics
    assert mine.preparation == from_cli.preparation


def test_saved_file_matches_cli_attributes(tmp_path, data_dir, cli):
    """Result.save writes the attributes the program writes (only the
    command line and the timing differ)."""
    height_map = data_dir / "di-5-crop-48x64.h5"
    output = tmp_path / "cli.h5"
    subprocess.run([cli, "solve", "--height-map", str(height_map), "--detrend", "mean", "--E-star", "1e9",
                    "--force", "1e-9", "--threads", "1", "--fft-planning", "estimate", "--output", str(output),
                    "--quiet"], check=True)
    mine = hs.solve(hs.read_height_map(height_map, detrend="mean"), e_star=1e9, force=1e-9, threads=1,
                    fft_planning="estimate")
    mine.save(tmp_path / "python.h5")
    cli_attributes = hs.read_result(output).attributes
    python_attributes = hs.read_result(tmp_path / "python.h5").attributes
    assert sorted(cli_attributes) == sorted(python_attributes)
    differing = {key for key in cli_attributes if cli_attributes[key] != python_attributes[key]}
    # The build identity differs when the program and the package were built at different commits.
    assert differing <= {"command_line", "solve_seconds", "halfspace_version"}, differing
    assert python_attributes["command_line"].startswith("python: halfspace.solve(")
