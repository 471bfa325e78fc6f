// Height maps in and out of Python: the readers with the preparation steps,
// the built-in and self-affine generators, and the surface statistics.
#include <fmt/format.h>
#include <nanobind/stl/filesystem.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "halfspace/error.hpp"
#include "halfspace/geometry/builtin_surface.hpp"
#include "halfspace/io/hdf5_output.hpp"
#include "halfspace/io/height_map_reader.hpp"
#include "halfspace/surface/preparation.hpp"
#include "halfspace/surface/self_affine.hpp"
#include "halfspace/surface/statistics.hpp"
#include "halfspace/surface/surface_options.hpp"

namespace halfspace::python {
namespace {

std::vector<std::size_t> shape_of(const HeightMap& map) {
  return map.dimension == 1 ? std::vector<std::size_t>{map.nx} : std::vector<std::size_t>{map.ny, map.nx};
}

Grid grid_of(std::size_t nx, std::size_t ny, int dimension, double dx, double dy, bool periodic) {
  const Boundary boundary = periodic ? Boundary::periodic : Boundary::free;
  return dimension == 1 ? Grid::line(nx, dx, boundary) : Grid::plane(nx, ny, dx, dy, boundary);
}

// What read_height_map and prepare hand back: the prepared map as a dict.
nb::dict map_dict(HeightMap&& map) {
  nb::dict out;
  out["shape"] = nb::cast(shape_of(map));
  out["dx"] = map.dx;
  out["dy"] = map.dy;
  out["source"] = map.source;
  out["preparation"] = nb::cast(map.preparation);
  out["heights"] = owning_array(std::move(map.heights), shape_of(map));
  return out;
}

// The preparation's keywords, checked by the library (surface_options.hpp).
surface::PreparationOptions preparation_options(const std::optional<std::string>& window, const std::string& invalid,
                                                const std::string& detrend, const std::optional<std::string>& resample,
                                                double pad) {
  return checked_preparation(
      {.window = window, .invalid = invalid, .detrend = detrend, .resample = resample, .pad = pad}, Boundary::free,
      KeywordSpelling());
}

void prepare(HeightMap& map, const surface::PreparationOptions& options) {
  try {
    surface::prepare_height_map(map, options);
  } catch (const FileError& error) {
    // Only the refusal of invalid points is a FileError here: say how to proceed.
    throw FileError(fmt::format("{} (pass invalid='fill' or invalid='crop')", error.what()));
  }
}

nb::dict read_map(const std::filesystem::path& path, const std::string& format, const std::string& dataset,
                  const std::optional<std::string>& unit, const std::optional<std::string>& window,
                  const std::string& invalid, const std::string& detrend, const std::optional<std::string>& resample,
                  std::optional<double> dx, std::optional<double> dy, double pad) {
  const KeywordSpelling keywords;
  const SurfaceOptions given{.height_map = path.string(),
                             .dataset = dataset,
                             .dx = dx,
                             .dy = dy,
                             .format = format,
                             .unit = unit,
                             .window = window,
                             .invalid = invalid,
                             .detrend = detrend,
                             .resample = resample,
                             .pad = pad};
  const HeightMapFile file = std::get<HeightMapFile>(make_surface_choice(given, Boundary::free, keywords));
  HeightMap map;
  {
    nb::gil_scoped_release release;
    map = io::read_height_map(path, file.read);
  }
  set_spacing(map, file, keywords);
  {
    nb::gil_scoped_release release;
    prepare(map, file.prepare);
  }
  return map_dict(std::move(map));
}

// An array's heights as a HeightMap with NaN (and inf) as invalid points.
HeightMap map_from(const InputArray& heights, double dx, double dy, const std::string& source) {
  check_array_dimensions(heights, "heights");
  HeightMap map;
  map.dimension = static_cast<int>(heights.ndim());
  map.nx = heights.shape(heights.ndim() - 1);
  map.ny = heights.ndim() == 2 ? heights.shape(0) : 1;
  map.dx = dx;
  map.dy = map.dimension == 2 ? dy : 0.0;
  map.source = source;
  map.heights = Eigen::Map<const Eigen::ArrayXd>(heights.data(), static_cast<Eigen::Index>(heights.size()));
  bool all_valid = true;
  for (std::size_t k = 0; k < map.size() && all_valid; ++k) all_valid = std::isfinite(map.heights[k]);
  if (!all_valid) {
    map.valid.resize(map.size());
    for (std::size_t k = 0; k < map.size(); ++k) {
      map.valid[k] = std::isfinite(map.heights[k]) ? 1 : 0;
      if (!map.valid[k]) map.heights[k] = std::nan("");
    }
  }
  return map;
}

nb::dict prepare_array(const InputArray& heights, double dx, double dy, const std::string& source,
                       const std::optional<std::string>& window, const std::string& invalid, const std::string& detrend,
                       const std::optional<std::string>& resample, double pad) {
  const surface::PreparationOptions options = preparation_options(window, invalid, detrend, resample, pad);
  HeightMap map = map_from(heights, dx, dy, source);
  {
    nb::gil_scoped_release release;
    prepare(map, options);
  }
  return map_dict(std::move(map));
}

OutputArray builtin(const std::string& shape, std::size_t nx, std::size_t ny, int dimension, double dx, double dy,
                    double radius, double wavelength, double amplitude) {
  geometry::SurfaceSpec spec;
  spec.shape = geometry::parse_surface_shape(shape);
  spec.radius = radius;
  spec.wavelength = wavelength;
  spec.amplitude = amplitude;
  const Grid grid = grid_of(nx, ny, dimension, dx, dy, false);
  Eigen::ArrayXd heights = geometry::make_surface_heights(grid, spec);
  return owning_array(std::move(heights), io::field_shape(grid));
}

nb::tuple self_affine(std::size_t nx, std::size_t ny, int dimension, double dx, double dy, double hurst,
                      double short_cutoff, double rolloff, double long_cutoff, std::optional<double> rms_height,
                      std::optional<double> rms_slope, std::uint64_t seed) {
  surface::SelfAffineSpec spec;
  spec.hurst = hurst;
  spec.short_cutoff = short_cutoff;
  spec.rolloff = rolloff;
  spec.long_cutoff = long_cutoff;
  spec.rms_height = rms_height;
  spec.rms_slope = rms_slope;
  spec.seed = seed;
  const Grid grid = grid_of(nx, ny, dimension, dx, dy, true);
  const surface::SelfAffineSpec resolved = spec.resolved(grid);
  Eigen::ArrayXd heights;
  {
    nb::gil_scoped_release release;
    heights = surface::make_self_affine_surface(grid, spec);
  }
  nb::dict used;
  used["hurst"] = resolved.hurst;
  used["cutoff_short"] = resolved.short_cutoff;
  used["rolloff"] = resolved.rolloff;
  used["cutoff_long"] = resolved.long_cutoff;
  return nb::make_tuple(owning_array(std::move(heights), io::field_shape(grid)), used);
}

nb::dict statistics(const InputArray& heights, double dx, double dy, bool periodic) {
  const Grid grid = array_grid(heights, dx, dy, periodic ? Boundary::periodic : Boundary::free, "heights");
  surface::SurfaceStatistics s;
  {
    nb::gil_scoped_release release;
    s = surface::surface_statistics(grid, values(heights));
  }
  nb::dict out;
  out["rms_height"] = s.rms_height;
  out["rms_slope"] = s.rms_slope;
  return out;
}

}  // namespace

void bind_surfaces(nb::module_& module) {
  module.def("read_height_map", &read_map, nb::arg("path"), nb::arg("format"), nb::arg("dataset"), nb::arg("unit"),
             nb::arg("window"), nb::arg("invalid"), nb::arg("detrend"), nb::arg("resample"), nb::arg("dx"),
             nb::arg("dy"), nb::arg("pad"));
  module.def("prepare", &prepare_array, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("source"),
             nb::arg("window"), nb::arg("invalid"), nb::arg("detrend"), nb::arg("resample"), nb::arg("pad"));
  module.def("builtin_surface", &builtin, nb::arg("shape"), nb::arg("nx"), nb::arg("ny"), nb::arg("dimension"),
             nb::arg("dx"), nb::arg("dy"), nb::arg("radius"), nb::arg("wavelength"), nb::arg("amplitude"));
  module.def("self_affine", &self_affine, nb::arg("nx"), nb::arg("ny"), nb::arg("dimension"), nb::arg("dx"),
             nb::arg("dy"), nb::arg("hurst"), nb::arg("cutoff_short"), nb::arg("rolloff"), nb::arg("cutoff_long"),
             nb::arg("rms_height").none(), nb::arg("rms_slope").none(), nb::arg("seed"));
  module.def("surface_statistics", &statistics, nb::arg("heights"), nb::arg("dx"), nb::arg("dy"), nb::arg("periodic"));
}

}  // namespace halfspace::python
