#!/usr/bin/env bash
# Builds the Python package into a virtual environment (`pip install .`, as
# the README says) and runs its tests (tests/python). The tests compare with
# the halfspace program, so scripts/build.sh must have run. The environment
# is kept between runs (HALFSPACE_PYTHON_VENV, default build/python-venv);
# the package's own build directory (build/python) and ccache make a second
# run quick.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${HALFSPACE_BUILD_DIR:-$root/build}"
venv="${HALFSPACE_PYTHON_VENV:-$root/build/python-venv}"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --upgrade pip
# numpy is the package's dependency; pytest, matplotlib (the example's
# figures) and pandas (Sweep.to_pandas) are the tests'; h5py and vtk (the
# reader ParaView uses, vtkXdmfReader) check the XDMF sidecars against the
# HDF5 files. Where vtk has no wheel for this platform those tests skip,
# naming why.
"$venv/bin/python" -m pip install --quiet numpy pytest matplotlib pandas h5py
"$venv/bin/python" -m pip install --quiet vtk || echo "test-python.sh: vtk could not be installed; the XDMF reader tests will skip" >&2
"$venv/bin/python" -m pip install --quiet "$root"
HALFSPACE_EXECUTABLE="$build/bin/halfspace" "$venv/bin/python" -m pytest -q -rs "$root/tests/python" "$@"
