// The surface's options (SurfaceOptions, halfspace/surface/surface_options.hpp)
// as rows of a command's option table, one each, for every command that
// takes a surface (solve, lubricate); the library checks them
// (make_surface_choice).
#pragma once

#include <array>
#include <string_view>

#include "halfspace/surface/surface_options.hpp"
#include "option_table.hpp"

namespace halfspace::app {

inline constexpr std::string_view kSurfaceGroup = "Surface (exactly one of --height-map, --geometry)";
inline constexpr std::string_view kPreparationGroup = "Height-map format and preparation (applied in this order)";
inline constexpr std::string_view kGridGroup = "Grid";

// The rows of the surface's options for the options struct `Options` (a
// SurfaceOptions); the pad factor is solve's own row.
template <class Options>
std::array<OptionSpec<Options>, 16> surface_option_table() {
  using Spec = OptionSpec<Options>;
  using Kind = OptionKind;
  return {
      Spec{"height-map", &Options::height_map, Kind::path, kSurfaceGroup, "FILE",
           "height map (m): a profile or a (ny, nx) map in any format --format reads; its grid is used"},
      Spec{"dataset", &Options::dataset, Kind::text, kSurfaceGroup, "PATH", "dataset in the height map file [/height]"},
      Spec{"dx", &Options::dx, Kind::number, kSurfaceGroup, "M",
           "height map spacing along x (m); overrides the file's dx attribute"},
      Spec{"dy", &Options::dy, Kind::number, kSurfaceGroup, "M",
           "height map spacing along y (m); overrides the file's dy attribute"},
      Spec{"format", &Options::format, Kind::text, kPreparationGroup, "NAME",
           "height map format: auto (by extension), hdf5, npy, matrix, profile, x3p or gsf [auto]"},
      Spec{"unit", &Options::unit, Kind::text, kPreparationGroup, "UNIT",
           "length unit of npy, text and unlabelled GSF files: m, mm, um, nm [m]"},
      Spec{"window", &Options::window, Kind::text, kPreparationGroup, "I0,J0,NX,NY",
           "use only columns I0..I0+NX-1 and rows J0..J0+NY-1 (0-based; I0,NX for a profile)"},
      Spec{"invalid", &Options::invalid, Kind::text, kPreparationGroup, "MODE",
           "invalid (masked or NaN) points: refuse, fill (harmonic) or crop (largest valid rectangle) [refuse]"},
      Spec{"detrend", &Options::detrend, Kind::text, kPreparationGroup, "MODE",
           "subtract a least-squares fit: none, mean, plane or curvature [none]"},
      Spec{"resample", &Options::resample, Kind::text, kPreparationGroup, "NXxNY",
           "resample onto NXxNY cells (N for a profile) over the same lengths: linear interpolation where finer, "
           "cell means where coarser (at most 16x finer)"},
      Spec{"geometry", &Options::geometry, Kind::text, kSurfaceGroup, "SHAPE",
           "built-in surface: sphere, cylinder, flat or wavy"},
      Spec{"radius", &Options::radius, Kind::number, kSurfaceGroup, "M", "sphere or cylinder radius (m)"},
      Spec{"wavelength", &Options::wavelength, Kind::number, kSurfaceGroup, "M", "wavy surface wavelength (m)"},
      Spec{"amplitude", &Options::amplitude, Kind::number, kSurfaceGroup, "M",
           "wavy surface amplitude A (m): h = -A (1 - cos ...)"},
      Spec{"grid", &Options::grid, Kind::dimensions, kGridGroup, "N|NXxNY",
           "cells of a built-in geometry: N (1D) or NXxNY (2D)"},
      Spec{"size", &Options::size, Kind::dimensions, kGridGroup, "L|LXxLY",
           "domain size of a built-in geometry (m), centred on its apex; spacing = L / N"},
  };
}

}  // namespace halfspace::app
