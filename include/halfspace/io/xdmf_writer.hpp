// XDMF sidecars: beside every HDF5 file of fields halfspace writes (result,
// sweep, height map, stress volume), a small XML file `<name>.xdmf` that
// tells ParaView, VisIt or any XDMF 2 reader (VTK's vtkXdmfReader) how the
// datasets form grids. It points into the HDF5 file by its name, copying no
// field values (layout in docs/file-format.md#xdmf-sidecars).
#pragma once

#include <filesystem>
#include <string>

#include "halfspace/grid.hpp"

namespace halfspace::io {

// Where the sidecar of `hdf5_path` goes: the same name with the extension
// .xdmf (result.h5 -> result.xdmf).
std::filesystem::path xdmf_sidecar_path(const std::filesystem::path& hdf5_path);

// The sidecar's XML for the complete HDF5 file at `hdf5_path`, whose fields
// lie on `grid`. It describes what the file holds, read from its structure
// (names, shapes and types; the values only of /stress/depths):
//  - the datasets of a group shaped like a field (float64 or uint8; (ny, nx)
//    in 2D, (nx) in 1D) as the attributes of one grid: in 2D cell-centred on
//    a uniform grid of one cell layer (3DCoRectMesh), the cell (i, j)
//    centred at x = i*dx, y = j*dy, z = dz/2 with dz = dx; in 1D
//    node-centred on a line of nx points at x = i*dx;
//  - /steps/NNN (a sweep) as a temporal collection, one grid per step at the
//    time value of its index, each with the step's fields and /height;
//  - /stress (a stress volume) as a 3D rectilinear grid (3DRectMesh,
//    VXVYVZ) with node-centred attributes: x = i*dx, y = j*dy and
//    z = -depth (the body below the surface z = 0).
// Throws FileError "cannot write XDMF sidecar for '<path>': <reason>" if the
// file cannot be read or holds nothing shaped like `grid`.
std::string xdmf_sidecar_text(const std::filesystem::path& hdf5_path, const Grid& grid);

// Checks before a long computation that the sidecar of the output
// `hdf5_path` can be written: InputError if it would be the output itself
// (an output named *.xdmf), FileError as check_output_path for its path.
void check_xdmf_sidecar_path(const std::filesystem::path& hdf5_path);

// Writes xdmf_sidecar_text to xdmf_sidecar_path(hdf5_path) through
// write_output_file (checked path, temporary name, rename). Throws
// InputError if the sidecar would be the HDF5 file itself (an output named
// *.xdmf), FileError naming the path if it cannot be written.
void write_xdmf_sidecar(const std::filesystem::path& hdf5_path, const Grid& grid);

}  // namespace halfspace::io
