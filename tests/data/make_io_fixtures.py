#!/usr/bin/env python3
"""Makes the small HDF5 fixtures of tests/io from the measured topographies in
../shared/data/topography beside the project (h5py 3.7, numpy 1.24). Run from anywhere:
    python3 tests/data/make_io_fixtures.py [topography_dir]
It prints the reference values that tests/io/hdf5_height_map_reader_test.cpp
records, computed here with numpy independently of the C++ reader."""
import os
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# The shared data sit beside the project root (tests/data/../..): <root>/../shared.
ROOT = os.path.dirname(os.path.dirname(HERE))
TOPOGRAPHY = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data", "topography")


def copy_attributes(source, target, **changes):
    for name, value in source.attrs.items():
        target.attrs[name] = changes.pop(name, value)
    for name, value in changes.items():
        target.attrs[name] = value


def fixed(text):
    """Fixed-length ASCII, as in the measured files."""
    return np.bytes_(text)


def crop_di5():
    rows, cols = slice(100, 148), slice(200, 264)  # ny = 48, nx = 64: nx != ny catches a transpose
    with h5py.File(os.path.join(TOPOGRAPHY, "di-5.h5"), "r") as src:
        h = src["height"][rows, cols]
        out = os.path.join(HERE, "di-5-crop-48x64.h5")
        with h5py.File(out, "w") as dst:
            dst.create_dataset("height", data=h)  # float64 LE, contiguous
            copy_attributes(src, dst, nx=np.int64(64), ny=np.int64(48),
                            cropped=fixed("rows 100:148 and columns 200:264 of di-5.h5 (0-based, end exclusive), "
                                          "made by tests/data/make_io_fixtures.py"))
    print(f"di-5 crop: shape {h.shape}, rms about mean {np.sqrt(np.mean((h - h.mean()) ** 2))!r}, "
          f"mean {h.mean()!r}, h[0,0] {h[0, 0]!r}, h[47,63] {h[47, 63]!r}, h[5,17] {h[5, 17]!r}")


def crop_dektak():
    with h5py.File(os.path.join(TOPOGRAPHY, "dektak-1.h5"), "r") as src:
        h = src["height"][:256]
        out = os.path.join(HERE, "dektak-1-crop-256.h5")
        with h5py.File(out, "w") as dst:
            dst.create_dataset("height", data=h)
            copy_attributes(src, dst, nx=np.int64(256),
                            cropped=fixed("points 0:256 of dektak-1.h5, made by tests/data/make_io_fixtures.py"))
    print(f"dektak-1 crop: shape {h.shape}, rms about mean {np.sqrt(np.mean((h - h.mean()) ** 2))!r}, "
          f"h[0] {h[0]!r}, h[255] {h[255]!r}")


def crop_sur2():
    # The two one-cell spikes of sur-2.h5 (rows 152, columns 259 and 260, 28 rms
    # heights above the mean) and the rough surface around them: the load-control
    # stall of Polonsky-Keer's scaling (tests/solvers/spiked_surface_test.cpp).
    rows, cols = slice(120, 184), slice(230, 294)
    with h5py.File(os.path.join(TOPOGRAPHY, "sur-2.h5"), "r") as src:
        h = src["height"][rows, cols]
        out = os.path.join(HERE, "sur-2-crop-64x64.h5")
        with h5py.File(out, "w") as dst:
            dst.create_dataset("height", data=h)
            copy_attributes(src, dst, nx=np.int64(64), ny=np.int64(64),
                            cropped=fixed("rows 120:184 and columns 230:294 of sur-2.h5 (0-based, end exclusive), "
                                          "made by tests/data/make_io_fixtures.py"))
    print(f"sur-2 crop: shape {h.shape}, rms about mean {np.sqrt(np.mean((h - h.mean()) ** 2))!r}, "
          f"highest {np.sort(h.ravel())[-3:]!r}")


def synthetic():
    # float32 storage; every value exactly representable so the conversion is exact.
    j, i = np.mgrid[0:3, 0:5]
    with h5py.File(os.path.join(HERE, "height-float32-3x5.h5"), "w") as f:
        f.create_dataset("height", data=((10 * j + i) * 0.5 - 3.0).astype(np.float32))
        f.attrs["dx"] = np.float32(2.5e-6)  # float32 attribute
        f.attrs["dy"] = np.int64(2)  # integer attribute
    # int16 profile in a non-default dataset, no spacing attributes.
    with h5py.File(os.path.join(HERE, "profile-int16.h5"), "w") as f:
        f.create_dataset("profile", data=np.array([-3, 0, 7, 12, -32768, 32767], dtype=np.int16))


if __name__ == "__main__":
    crop_di5()
    crop_dektak()
    crop_sur2()
    synthetic()
