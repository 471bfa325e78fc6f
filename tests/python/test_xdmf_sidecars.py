"""The XDMF sidecars beside every HDF5 file, opened with the reader ParaView
uses (VTK's vtkXdmfReader) and compared with the HDF5 file read by h5py:
names, shapes, spacing, coordinates and values (docs/file-format.md#xdmf-sidecars)."""

import subprocess

import numpy as np
import pytest

import halfspace as hs

h5py = pytest.importorskip("h5py", reason="h5py is not installed (scripts/test-python.sh installs it)")
xdmf2 = pytest.importorskip(
    "vtkmodules.vtkIOXdmf2", reason="the vtk wheel is not installed (no wheel for this platform or Python?)")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline  # noqa: E402


def read(xdmf, time=None):
    """The reader's output: a list of (grid name, dataset) per block."""
    reader = xdmf2.vtkXdmfReader()
    reader.SetFileName(str(xdmf))
    reader.UpdateInformation()
    if time is None:
        reader.Update()
    else:
        reader.UpdateTimeStep(time)
    output = reader.GetOutputDataObject(0)
    if output.IsA("vtkMultiBlockDataSet"):
        return [(output.GetMetaData(k).Get(output.NAME()), output.GetBlock(k))
                for k in range(output.GetNumberOfBlocks())], reader
    return [(None, output)], reader


def arrays(data):
    """name -> numpy array of the cell data (2D) or point data (1D, stress)."""
    out = {}
    for attributes in (data.GetCellData(), data.GetPointData()):
        for k in range(attributes.GetNumberOfArrays()):
            out[attributes.GetArrayName(k)] = vtk_to_numpy(attributes.GetArray(k))
    return out


def field_datasets(group, shape):
    return {name: group[name][()] for name in group
            if isinstance(group[name], h5py.Dataset) and group[name].shape == shape}


def check_surface(data, fields, nx, ny, dx, dy):
    """A 2D surface grid: one layer of nx x ny cells centred at (i dx, j dy)."""
    assert data.IsA("vtkImageData")
    assert data.GetDimensions() == (nx + 1, ny + 1, 2)
    assert data.GetSpacing() == pytest.approx((dx, dy, dx), rel=1e-15)
    assert data.GetOrigin() == pytest.approx((-dx / 2, -dy / 2, 0.0), rel=1e-15)
    assert data.GetNumberOfCells() == nx * ny
    got = arrays(data)
    assert set(got) == set(fields)
    for name, values in fields.items():
        # Cell order: x fastest, like the (ny, nx) row-major dataset.
        assert got[name].dtype == values.dtype, name
        np.testing.assert_array_equal(got[name], values.ravel(), err_msg=name)


def run(cli, *args, cwd):
    subprocess.run([cli, *map(str, args), "--quiet"], check=True, cwd=cwd)


@pytest.fixture
def rough(tmp_path, cli):
    run(cli, "generate", "--kind", "self-affine", "--grid", "24x16", "--size", "1.2e-3x0.8e-3", "--rms-height",
        "1e-6", "--seed", "3", "--output", "surface.h5", cwd=tmp_path)
    return tmp_path


def test_height_map_sidecar(rough):
    blocks, _ = read(rough / "surface.xdmf")
    assert len(blocks) == 1
    with h5py.File(rough / "surface.h5") as f:
        fields = field_datasets(f, (16, 24))
        assert set(fields) == {"height"}
        check_surface(blocks[0][1], fields, 24, 16, f.attrs["dx"], f.attrs["dy"])


def test_result_sidecar_with_hardness(rough, cli):
    run(cli, "solve", "--height-map", "surface.h5", "--boundary", "periodic", "--E-star", "1e9", "--hardness",
        "3e6", "--mean-pressure", "1e6", "--output", "result.h5", cwd=rough)
    blocks, _ = read(rough / "result.xdmf")
    with h5py.File(rough / "result.h5") as f:
        fields = field_datasets(f, (16, 24))
        assert {"height", "pressure", "gap", "displacement", "contact", "plastic", "plastic_displacement"} == set(fields)
        assert fields["plastic"].any()  # the cap is reached: the field is not trivially zero
        check_surface(blocks[0][1], fields, 24, 16, f.attrs["dx"], f.attrs["dy"])


def test_one_dimensional_result_is_a_line(tmp_path, cli):
    run(cli, "solve", "--geometry", "cylinder", "--radius", "0.01", "--grid", "64", "--size", "2e-4", "--E-star",
        "1e11", "--force", "1000", "--output", "line.h5", cwd=tmp_path)
    blocks, _ = read(tmp_path / "line.xdmf")
    data = blocks[0][1]
    with h5py.File(tmp_path / "line.h5") as f:
        dx = f.attrs["dx"]
        fields = field_datasets(f, (64,))
        assert data.GetDimensions() == (64, 1, 1)
        assert data.GetSpacing()[0] == pytest.approx(dx, rel=1e-15)
        assert data.GetOrigin() == (0.0, 0.0, 0.0)
        assert data.GetPoint(63) == pytest.approx((63 * dx, 0.0, 0.0), rel=1e-15)
        got = arrays(data)
        assert set(got) == set(fields) == {"height", "pressure", "gap", "displacement", "contact"}
        for name, values in fields.items():
            np.testing.assert_array_equal(got[name], values, err_msg=name)
        assert data.GetPointData().GetArray("pressure") is not None  # node-centred


def test_sweep_sidecar_is_a_temporal_collection(rough, cli):
    run(cli, "solve", "--height-map", "surface.h5", "--boundary", "periodic", "--E-star", "1e9", "--mean-pressure",
        "1e6:3e6:3", "--output", "sweep.h5", cwd=rough)
    _, reader = read(rough / "sweep.xdmf")
    times = reader.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert times == (0.0, 1.0, 2.0)
    with h5py.File(rough / "sweep.h5") as f:
        steps = sorted(f["steps"])
        assert len(steps) == 3
        for k, step in enumerate(steps):
            blocks, _ = read(rough / "sweep.xdmf", time=float(k))
            fields = field_datasets(f["steps"][step], (16, 24))
            fields["height"] = f["height"][()]
            check_surface(blocks[0][1], fields, 24, 16, f.attrs["dx"], f.attrs["dy"])
        # The steps differ: the time steps are not one grid read three times.
        assert not np.array_equal(f["steps"][steps[0]]["pressure"][()], f["steps"][steps[2]]["pressure"][()])


@pytest.mark.parametrize("grid,size,shape", [("24x16", "1.2e-3x0.8e-3", (16, 24)), ("48", "1.2e-3", (48,))])
def test_stress_volume_sidecar(tmp_path, cli, grid, size, shape):
    run(cli, "solve", "--geometry", "sphere" if len(shape) == 2 else "cylinder", "--radius", "0.01", "--grid", grid,
        "--size", size, "--E-star", "1e9", "--approach", "2e-6", "--output", "result.h5", cwd=tmp_path)
    run(cli, "stress", "result.h5", "--depths", "1e-5,3e-5,1e-4,2.5e-4", "--nu", "0.3", "--output", "stress.h5",
        cwd=tmp_path)
    blocks, _ = read(tmp_path / "stress.xdmf")
    names = [name for name, _ in blocks]
    assert names == ["surface", "stress"]
    volume = blocks[1][1]
    assert volume.IsA("vtkRectilinearGrid")
    ny, nx = (1, *shape) if len(shape) == 1 else shape
    with h5py.File(tmp_path / "stress.h5") as f:
        depths = f["stress/depths"][()]
        dx = f.attrs["dx"]
        assert volume.GetDimensions() == (nx, ny, len(depths))
        np.testing.assert_allclose(vtk_to_numpy(volume.GetXCoordinates()), np.arange(nx) * dx, rtol=1e-15)
        expected_y = [0.0] if len(shape) == 1 else np.arange(ny) * f.attrs["dy"]
        np.testing.assert_allclose(vtk_to_numpy(volume.GetYCoordinates()), expected_y, rtol=1e-15)
        np.testing.assert_array_equal(vtk_to_numpy(volume.GetZCoordinates()), -depths)
        fields = field_datasets(f["stress"], (len(depths), *shape))
        assert {"von_mises", "sigma_zz", "sigma_xz", "max_shear", "hydrostatic"} <= set(fields)
        got = arrays(volume)
        assert set(got) == set(fields)
        for name, values in fields.items():
            np.testing.assert_array_equal(got[name], values.ravel(), err_msg=name)
        assert np.abs(fields["von_mises"]).max() > 0
        surface = arrays(blocks[0][1])
        assert set(surface) == {"pressure"}
        np.testing.assert_array_equal(surface["pressure"], f["pressure"][()].ravel())


def test_python_save_writes_the_sidecar(tmp_path):
    surface = hs.generate.self_affine(grid=(20, 12), size=(1e-3, 0.6e-3), rms_slope=0.1, seed=5)
    result = hs.solve(surface, mean_pressure=1e6, e_star=1e9, boundary="periodic", fft_planning="estimate",
                      threads=1)
    result.save(tmp_path / "r.h5")
    blocks, _ = read(tmp_path / "r.xdmf")
    with h5py.File(tmp_path / "r.h5") as f:
        check_surface(blocks[0][1], field_datasets(f, (12, 20)), 20, 12, f.attrs["dx"], f.attrs["dy"])
    sweep = hs.sweep(surface, mean_pressure=[1e6, 2e6], e_star=1e9, boundary="periodic", fft_planning="estimate",
                     threads=1)
    sweep.save(tmp_path / "s.h5")
    _, reader = read(tmp_path / "s.xdmf")
    assert reader.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS()) == (0.0, 1.0)


def test_result_with_stress_group_has_both_grids(tmp_path, cli):
    run(cli, "solve", "--geometry", "sphere", "--radius", "0.01", "--grid", "16x16", "--size", "5e-4", "--E-star",
        "1e11", "--force", "1", "--stress-depths", "1e-5,2e-5,4e-5", "--stress-nu", "0.3", "--output", "result.h5",
        cwd=tmp_path)
    blocks, _ = read(tmp_path / "result.xdmf")
    assert [name for name, _ in blocks] == ["surface", "stress"]
    with h5py.File(tmp_path / "result.h5") as f:
        check_surface(blocks[0][1], field_datasets(f, (16, 16)), 16, 16, f.attrs["dx"], f.attrs["dy"])
        volume = blocks[1][1]
        np.testing.assert_array_equal(vtk_to_numpy(volume.GetZCoordinates()), -f["stress/depths"][()])
        np.testing.assert_array_equal(arrays(volume)["sigma_zz"], f["stress/sigma_zz"][()].ravel())
