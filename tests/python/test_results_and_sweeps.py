"""Result.save / read_result round trips, sweeps and their tables, reprs,
and the paper's Table 1 from Python."""

import csv

import numpy as np
import pytest

import halfspace as hs

SURFACE = hs.generate.self_affine(grid=(64, 48), size=(1e-3, 0.75e-3), rms_slope=0.1, seed=7)
SOLVE = dict(e_star=1e9, boundary="periodic", fft_planning="estimate", threads=1)


def test_save_read_round_trip(tmp_path):
    result = hs.solve(SURFACE, mean_pressure=1e6, **SOLVE)
    result.save(tmp_path / "r.h5")
    back = hs.read_result(tmp_path / "r.h5")
    for field in ("pressure", "gap", "displacement", "contact", "heights", "residual_history"):
        assert np.array_equal(getattr(result, field), getattr(back, field)), field
    for number in ("iterations", "residual", "tolerance", "approach", "total_force", "mean_pressure",
                   "contact_fraction", "max_pressure", "converged", "status", "message", "solver", "e_star",
                   "load_mode", "dx", "dy", "boundary", "shape", "height_source", "threads"):
        assert getattr(result, number) == getattr(back, number), number
    assert result.statistics == back.statistics
    # A file records the reached load, not the imposed one: equal to rounding.
    assert back.load == pytest.approx(result.load, rel=1e-14)
    assert back.attributes["format"] == "halfspace-result"
    # Saving what was read writes the same fields again.
    back.save(tmp_path / "again.h5")
    assert np.array_equal(hs.read_result(tmp_path / "again.h5").pressure, result.pressure)


def test_result_fields_and_repr():
    result = hs.solve(SURFACE, mean_pressure=1e6, **SOLVE)
    assert result.pressure.shape == result.gap.shape == result.displacement.shape == (48, 64)
    assert result.contact.dtype == np.bool_
    assert np.array_equal(result.contact, result.pressure > 0)
    assert result.contact_fraction == pytest.approx(result.contact.mean(), abs=1e-15)
    assert result.mean_pressure == pytest.approx(1e6, rel=1e-9)
    assert result.statistics["clusters"] == len(result.statistics["cluster_sizes"]) > 0
    text = repr(result)
    assert "64x48" in text and "converged" in text and result.solver in text
    assert "HeightMap(64x48" in repr(SURFACE)


def test_sweep_table_steps_and_files(tmp_path):
    loads = [2e5, 5e5, 1e6]
    sweep = hs.sweep(SURFACE, mean_pressure=loads, **SOLVE)
    assert len(sweep) == 3 and "3 steps" in repr(sweep)
    table = sweep.table
    assert np.array_equal(table["load"], loads)
    assert np.all(np.diff(table["contact_fraction"]) > 0)
    assert [step.warm_started for step in sweep.steps] == [False, True, True]
    # Each step equals a cold solve at its load to the tolerance (the warm start changes the path, not the answer).
    cold = hs.solve(SURFACE, mean_pressure=loads[-1], **SOLVE)
    assert np.max(np.abs(sweep[-1].pressure - cold.pressure)) < 1e-6 * cold.max_pressure
    sweep.save(tmp_path / "sweep.h5")
    with open(tmp_path / "sweep.csv") as file:
        rows = list(csv.DictReader(file))
    assert [float(row["load"]) for row in rows] == loads
    middle = hs.read_result(tmp_path / "sweep.h5", step=1)
    assert np.array_equal(middle.pressure, sweep[1].pressure)
    assert np.array_equal(hs.read_result(tmp_path / "sweep.h5").pressure, sweep[2].pressure)
    with pytest.raises(hs.FileError, match="step 5 is out of range"):
        hs.read_result(tmp_path / "sweep.h5", step=5)


def test_sweep_to_pandas():
    pandas = pytest.importorskip("pandas")
    frame = hs.sweep(SURFACE, mean_pressure=[1e5, 2e5], **SOLVE).to_pandas()
    assert isinstance(frame, pandas.DataFrame) and list(frame["load"]) == [1e5, 2e5]


def test_paper_table1_test1():
    table = hs.paper.reproduce(test=1, load=1e5)
    summary = table["summary"]
    assert summary["all_converged"]
    for column in ("x", "gap", "p_lemke", "p_lcpquad", "p_pk", "p_hertz"):
        assert table[column].shape == (summary["nodes"],)
    # The three methods solve the same discrete problem (tolerances 1e-10 to 1e-12).
    assert summary["lemke_vs_pk"] < 1e-6
    assert np.max(np.abs(table["p_pk"] - table["p_lemke"])) / summary["hertz_peak"] < 1e-6
