// The surface of a problem as a front end gives it, and the one place its
// rules live: a height-map file (its format, dataset, unit, spacing and
// preparation) or a built-in shape on a grid of given cells and size. The
// program maps its flags onto SurfaceOptions (solve and lubricate alike);
// make_surface_choice checks them and every message names the option as the
// front end spells it (OptionSpelling, problem.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/height_map.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/problem.hpp"
#include "halfspace/surface/preparation.hpp"

namespace halfspace {

// Exactly one of height_map and geometry; the options of the other are
// refused. Lengths in m; unset means not given.
struct SurfaceOptions {
  // A height-map file: how it is read (format "auto", hdf5, npy, matrix,
  // profile, x3p or gsf; an HDF5 dataset; the length unit of files that
  // state none), the spacings that override the file's, and its preparation
  // (surface/preparation.hpp: window "I0,J0,NX,NY", invalid points, detrend,
  // resample "NXxNY", pad factor of a free boundary).
  std::optional<std::string> height_map{};
  std::optional<std::string> dataset{};
  std::optional<double> dx{};
  std::optional<double> dy{};
  std::optional<std::string> format{};
  std::optional<std::string> unit{};
  std::optional<std::string> window{};
  std::optional<std::string> invalid{};
  std::optional<std::string> detrend{};
  std::optional<std::string> resample{};
  std::optional<double> pad{};
  // A built-in shape (sphere, cylinder, flat, wavy) and the lengths it needs,
  // on a grid of `grid` cells ("N" or "NXxNY") over `size` ("L" or "LXxLY").
  std::optional<std::string> geometry{};
  std::optional<double> radius{};
  std::optional<double> wavelength{};
  std::optional<double> amplitude{};
  std::optional<std::string> grid{};
  std::optional<std::string> size{};
};

// A height-map file as checked: how to read and prepare it.
struct HeightMapFile {
  std::string path;
  io::ReadOptions read{};
  surface::PreparationOptions prepare{};
  std::optional<double> dx{};  // checked spacings that override the file's
  std::optional<double> dy{};
};

// A built-in shape, and the shape on its grid.
struct BuiltinShape {
  geometry::SurfaceSpec spec;
  std::string source;  // "sphere (radius = 0.01 m)"
};
struct BuiltinSurface {
  BuiltinShape shape;
  Grid grid;
};

using SurfaceChoice = std::variant<HeightMapFile, BuiltinSurface>;

// Checks `options` on a grid of `boundary` (a pad factor needs a free one).
// Throws InputError naming the options as `spelling` writes them: both
// surfaces or none, an option of the other surface, a value that does not
// parse or lies outside its range.
SurfaceChoice make_surface_choice(const SurfaceOptions& options, Boundary boundary,
                                  const OptionSpelling& spelling = {});

// The preparation of a height map on a grid of `boundary`: the window,
// invalid points, detrending and pad factor of `options` (the others are
// not looked at). Throws InputError naming them.
surface::PreparationOptions checked_preparation(const SurfaceOptions& options, Boundary boundary,
                                                const OptionSpelling& spelling = {});

// Sets the spacing of `map`, read from `file`: the checked override, else
// the file's attribute, which must lie in the range of lengths. Throws
// InputError for a dy on a profile or a spacing out of range, FileError
// naming every spacing the file does not state and the option that gives it.
void set_spacing(HeightMap& map, const HeightMapFile& file, const OptionSpelling& spelling = {});

// The whole map of `file`: read, its spacing set (set_spacing) and prepared
// (surface::prepare_height_map). Throws as they do; a refusal of invalid
// points says how to proceed (with_invalid_points_hint).
HeightMap read_height_map_file(const HeightMapFile& file, const OptionSpelling& spelling = {});

// The refusal of a map's invalid points, `error`, with how to proceed:
// "(pass --invalid fill or --invalid crop)" in the front end's spelling.
FileError with_invalid_points_hint(const FileError& error, const OptionSpelling& spelling = {});

// The grid of `cells` ("N" or "NXxNY", at least 2 per axis, at most
// kMaxGridCells in all) over `size` ("L" or "LXxLY" m; one length on a 2D
// grid is a square), whose spacings lie in the range of lengths. The
// options are named `cells_option` and `size_option`. Throws InputError.
Grid grid_from_text(std::string_view cells, std::string_view size, Boundary boundary,
                    const OptionSpelling& spelling = {}, std::string_view cells_option = "grid",
                    std::string_view size_option = "size");

// The built-in shape `shape`, chosen by the option `shape_option` with the
// value `shape_text`, with the lengths it needs from radius, wavelength and
// amplitude (each positive and in the range of lengths); the others refused.
// Throws InputError naming the options.
BuiltinShape builtin_shape(std::string_view shape_option, std::string_view shape_text, geometry::SurfaceShape shape,
                           const std::optional<double>& radius, const std::optional<double>& wavelength,
                           const std::optional<double>& amplitude, const OptionSpelling& spelling = {});

// A length option: positive, finite and in the range of lengths. Throws
// InputError naming it.
double checked_length(std::string_view option, double value, const OptionSpelling& spelling = {});

}  // namespace halfspace
