"""Shared fixtures of the Python package's tests: paths to the test data and
to the halfspace program (for the comparisons with `halfspace solve`)."""

import os
import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data"
# ../shared beside the project root (the measured originals and conversions).
SHARED_TOPOGRAPHY = ROOT.parent / "shared" / "data" / "topography"


@pytest.fixture
def data_dir():
    return DATA


@pytest.fixture
def shared_topography():
    if not SHARED_TOPOGRAPHY.is_dir():
        pytest.fail(f"the shared topography data is missing: {SHARED_TOPOGRAPHY} (../shared beside the project root)")
    return SHARED_TOPOGRAPHY


@pytest.fixture
def cli():
    """The halfspace program: HALFSPACE_EXECUTABLE, else the build directory's, else on PATH."""
    candidates = [os.environ.get("HALFSPACE_EXECUTABLE"),
                  str(pathlib.Path(os.environ.get("HALFSPACE_BUILD_DIR", ROOT / "build")) / "bin" / "halfspace"),
                  shutil.which("halfspace")]
    for candidate in candidates:
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    pytest.fail("the halfspace program is needed: build it (scripts/build.sh) or set HALFSPACE_EXECUTABLE")
