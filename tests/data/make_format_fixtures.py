#!/usr/bin/env python3
"""Makes the fixtures of the height-map format readers (tests/io/*_reader_test.cpp)
from committed HDF5 crops of the measured topographies and, for the X3P and
Dektak files, from the originals in ../shared/data/topography beside the project (numpy 1.24,
h5py 3.7, only the standard library otherwise). Run from anywhere:
    python3 tests/data/make_format_fixtures.py [topography_dir]
Every binary fixture holds the same numbers as its source bit for bit; the text
ones print them with %.17g, which reads back exactly. The script prints the
reference values that the tests record, computed here with numpy independently
of the C++ readers."""
import hashlib
import os
import shutil
import struct
import sys
import zipfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# The shared data sit beside the project root (tests/data/../..): <root>/../shared.
ROOT = os.path.dirname(os.path.dirname(HERE))
TOPOGRAPHY = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "..", "shared", "data", "topography")
FIXED_DATE = (1980, 1, 1, 0, 0, 0)  # reproducible zip members


def di5_crop():
    """The 48 x 64 crop of di-5.h5 (made by make_io_fixtures.py), metres."""
    with h5py.File(os.path.join(HERE, "di-5-crop-48x64.h5"), "r") as f:
        return f["height"][...]


def write_npy(h):
    # C and Fortran order, little- and big-endian float64, and float32.
    variants = {
        "di-5-crop-c-le-f8.npy": np.ascontiguousarray(h, dtype="<f8"),
        "di-5-crop-c-be-f8.npy": np.ascontiguousarray(h, dtype=">f8"),
        "di-5-crop-f-le-f8.npy": np.asfortranarray(h, dtype="<f8"),
        "di-5-crop-f-be-f8.npy": np.asfortranarray(h, dtype=">f8"),
        "di-5-crop-c-le-f4.npy": np.ascontiguousarray(h, dtype="<f4"),
    }
    for name, array in variants.items():
        np.save(os.path.join(HERE, name), array)
    print(f"npy: {len(variants)} files of shape {h.shape}; float32 h[5,17] = {float(np.float32(h[5, 17]))!r}")


def write_text(h):
    # Whitespace separated, plain "\n" lines.
    with open(os.path.join(HERE, "di-5-crop-space.txt"), "w", newline="\n") as f:
        for row in h:
            f.write(" ".join(f"{v:.17g}" for v in row) + "\n")
    # Comma separated with comment lines and Windows line ends.
    with open(os.path.join(HERE, "di-5-crop-comma.csv"), "w", newline="") as f:
        f.write("# di-5.h5 rows 100:148, columns 200:264, heights in m\r\n")
        f.write("% written by tests/data/make_format_fixtures.py\r\n")
        for row in h:
            f.write(",".join(f"{v:.17g}" for v in row) + "\r\n")
    print("text: di-5-crop-space.txt, di-5-crop-comma.csv")


def gsf_bytes(h32, fields):
    """Gwyddion Simple Field: magic line, name = value lines, 1-4 NULs to a multiple of 4, float32 LE."""
    header = "Gwyddion Simple Field 1.0\n" + "".join(f"{k} = {v}\n" for k, v in fields.items())
    raw = header.encode("utf-8")
    raw += b"\0" * (4 - len(raw) % 4)
    return raw + np.ascontiguousarray(h32, dtype="<f4").tobytes()


def write_gsf(h, dx, dy):
    ny, nx = h.shape
    metres = gsf_bytes(h.astype(np.float32), {
        "XRes": nx, "YRes": ny, "XReal": repr(nx * dx), "YReal": repr(ny * dy),
        "XYUnits": "m", "ZUnits": "m", "Title": "di-5 crop"})
    with open(os.path.join(HERE, "di-5-crop-m.gsf"), "wb") as f:
        f.write(metres)
    # The same surface in nanometres and micrometres, as Gwyddion may store it.
    micro = gsf_bytes((h * 1e9).astype(np.float32), {
        "XRes": nx, "YRes": ny, "XReal": repr(nx * dx * 1e6), "YReal": repr(ny * dy * 1e6),
        "XYUnits": "um", "ZUnits": "nm"})
    with open(os.path.join(HERE, "di-5-crop-um-nm.gsf"), "wb") as f:
        f.write(micro)
    print(f"gsf: XReal {nx * dx!r}, header ends aligned; nm file h[5,17] = "
          f"{float(np.float32(h[5, 17] * 1e9)) * 1e-9!r}")


def write_profiles():
    with h5py.File(os.path.join(HERE, "dektak-1-crop-256.h5"), "r") as f:
        z = f["height"][...]
        dx = float(f.attrs["dx"])
    # x in um and z in nm, named in a header line.
    with open(os.path.join(HERE, "dektak-1-crop-x-z.txt"), "w", newline="\n") as f:
        f.write("# points 0:256 of dektak-1.h5\n")
        f.write("x [um]\tz [nm]\n")
        for k, v in enumerate(z):
            f.write(f"{k * dx * 1e6:.17g}\t{v * 1e9:.17g}\n")
    shutil.copyfile(os.path.join(TOPOGRAPHY, "dektak-1.csv"), os.path.join(HERE, "dektak-1.csv"))
    print(f"profiles: dektak-1-crop-x-z.txt ({len(z)} points), dektak-1.csv copied")


def x3p_zip(path, xml, members):
    """An X3P container: main.xml, its MD5 in md5checksum.hex, and the binary members."""
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for name, content in [("main.xml", xml)] + members + [
                ("md5checksum.hex", f"{hashlib.md5(xml).hexdigest()} *main.xml\n".encode())]:
            info = zipfile.ZipInfo(name, date_time=FIXED_DATE)
            info.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(info, content)


def write_kautschuk_crop():
    """Rows 0:40, columns 520:576 of KautschukInfiniteFocus.x3p, re-packed with the original main.xml: row 0 is
    fully invalid, row 1 invalid up to column 548 (the instrument's invalid points all lie along the edges)."""
    source = os.path.join(TOPOGRAPHY, "KautschukInfiniteFocus.x3p")
    with zipfile.ZipFile(source) as archive:
        xml = archive.read("main.xml").decode("utf-8")
        data = np.frombuffer(archive.read("bindata/data.bin"), dtype="<f4").reshape(634, 860)
    crop = np.ascontiguousarray(data[0:40, 520:576])
    binary = crop.tobytes()
    xml = xml.replace("<SizeX>860</SizeX>", "<SizeX>56</SizeX>").replace("<SizeY>634</SizeY>", "<SizeY>40</SizeY>")
    xml = xml.replace("66FE5D6CA054D345018FFC7448708525", hashlib.md5(binary).hexdigest().upper())
    x3p_zip(os.path.join(HERE, "kautschuk-crop-40x56.x3p"), xml.encode("utf-8"), [("bindata/data.bin", binary)])
    bad = ~np.isfinite(crop)
    kept = crop[1:40, :].astype(np.float64)  # the fully invalid row 0 cut
    print(f"x3p crop: {bad.sum()} invalid of {crop.size}; after cutting the border {(~np.isfinite(kept)).sum()} "
          f"invalid of {kept.size}; h[1,29] = {float(crop[1, 29])!r}, h[39,55] = {float(crop[39, 55])!r}, "
          f"rms of valid points about their mean {np.std(crop[~bad].astype(np.float64))!r}")


def write_x3p_int16_with_mask():
    """A 5 x 3 int16 surface with CZ increment and offset, and a validity bit mask."""
    values = np.arange(15, dtype="<i2").reshape(3, 5) * 100 - 700
    valid = np.ones(15, dtype=bool)
    valid[[1, 8, 14]] = False  # (j, i) = (0, 1), (1, 3), (2, 4)
    bits = np.packbits(valid, bitorder="little").tobytes()  # least significant bit first
    binary = values.tobytes()
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1.5e-06</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2.5e-06</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>I</DataType><Increment>1e-09</Increment><Offset>2e-06</Offset></CZ>
    </Axes>
  </Record1>
  <Record3>
    <MatrixDimension><SizeX>5</SizeX><SizeY>3</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataLink>
      <PointDataLink>bindata/data.bin</PointDataLink>
      <MD5ChecksumPointData>{hashlib.md5(binary).hexdigest().upper()}</MD5ChecksumPointData>
      <ValidPointsLink>bindata/valid.bin</ValidPointsLink>
      <MD5ChecksumValidPoints>{hashlib.md5(bits).hexdigest().upper()}</MD5ChecksumValidPoints>
    </DataLink>
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
""".encode("utf-8")
    x3p_zip(os.path.join(HERE, "int16-mask-5x3.x3p"), xml,
            [("bindata/data.bin", binary), ("bindata/valid.bin", bits)])
    print(f"x3p int16: stored {values.ravel().tolist()}, valid bits {bits.hex()}")


def write_x3p_text_profile():
    """A profile (PRF) with its z written as text, one Datum empty (invalid)."""
    z = ["1.5e-07", "", "-2.25e-07", "3e-08", "0"]
    data = "".join(f"<Datum>{v}</Datum>" for v in z)
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>PRF</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>5e-07</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>1</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>D</DataType></CZ>
    </Axes>
  </Record1>
  <Record3>
    <MatrixDimension><SizeX>5</SizeX><SizeY>1</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataList>{data}</DataList>
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
""".encode("utf-8")
    x3p_zip(os.path.join(HERE, "profile-datalist-5.x3p"), xml, [])
    print("x3p text profile: profile-datalist-5.x3p")


if __name__ == "__main__":
    h = di5_crop()
    with h5py.File(os.path.join(HERE, "di-5-crop-48x64.h5"), "r") as f:
        dx, dy = float(f.attrs["dx"]), float(f.attrs["dy"])
    write_npy(h)
    write_text(h)
    write_gsf(h, dx, dy)
    write_profiles()
    write_kautschuk_crop()
    write_x3p_int16_with_mask()
    write_x3p_text_profile()
