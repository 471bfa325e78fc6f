// The surface's options (surface/surface_options.hpp): the rules the program's
// solve and lubricate share with Python's reader, each message naming the
// option as the front end spells it.
#include "halfspace/surface/surface_options.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "halfspace/error.hpp"
#include "support/flag_spelling.hpp"

namespace halfspace {
namespace {

using Flags = testing::FlagSpelling;  // a program's spelling ("--name value")
using testing::refusal;

SurfaceOptions sphere() {
  return {.geometry = "sphere", .radius = 0.01, .grid = "64x32", .size = "1e-3"};
}

TEST(SurfaceOptionsTest, ExactlyOneSurface) {
  EXPECT_EQ(refusal([] { make_surface_choice({}, Boundary::free, Flags()); }),
            "no surface given: pass --height_map FILE or --geometry sphere|cylinder|flat|wavy");
  SurfaceOptions both = sphere();
  both.height_map = "map.h5";
  EXPECT_EQ(refusal([&] { make_surface_choice(both, Boundary::free, Flags()); }),
            "--height_map and --geometry cannot be combined: give exactly one surface");
}

TEST(SurfaceOptionsTest, BuiltinShapeOnItsGrid) {
  const SurfaceChoice choice = make_surface_choice(sphere(), Boundary::periodic, Flags());
  const auto& builtin = std::get<BuiltinSurface>(choice);
  EXPECT_EQ(builtin.shape.spec.shape, geometry::SurfaceShape::sphere);
  EXPECT_DOUBLE_EQ(builtin.shape.spec.radius, 0.01);
  EXPECT_EQ(builtin.shape.source, "sphere (radius = 0.01 m)");
  EXPECT_EQ(builtin.grid.nx(), 64U);
  EXPECT_EQ(builtin.grid.ny(), 32U);
  // One length on a 2D grid is a square domain.
  EXPECT_DOUBLE_EQ(builtin.grid.dx(), 1e-3 / 64);
  EXPECT_DOUBLE_EQ(builtin.grid.dy(), 1e-3 / 32);
  EXPECT_TRUE(builtin.grid.periodic());
}

TEST(SurfaceOptionsTest, BuiltinShapeRefusesTheFileOptions) {
  SurfaceOptions options = sphere();
  options.detrend = "plane";
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--detrend applies only to --height_map; a built-in geometry takes its spacing from --grid and --size");
  options = sphere();
  options.wavelength = 1e-4;
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--wavelength does not apply to --geometry sphere");
  options = sphere();
  options.radius.reset();
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--geometry sphere needs --radius (m)");
  options = sphere();
  options.radius = -1.0;
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--radius -1 is invalid: must be positive (m)");
  options = sphere();
  options.geometry = "cone";
  EXPECT_NE(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }).find("--geometry: "),
            std::string::npos);
  options = sphere();
  options.size.reset();
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--geometry needs --size L or LXxLY (domain size in m)");
}

TEST(SurfaceOptionsTest, GridTextIsChecked) {
  EXPECT_EQ(refusal([] { grid_from_text("1x8", "1e-3", Boundary::free, Flags()); }),
            "--grid 1x8 is invalid: need at least 2 cells along each axis (got nx = 1)");
  EXPECT_EQ(refusal([] { grid_from_text("64", "1e-3x2e-3", Boundary::free, Flags()); }),
            "--size 1e-3x2e-3 is invalid for the 1D grid --grid 64: give one length");
  EXPECT_EQ(refusal([] { grid_from_text("64", "abc", Boundary::free, Flags()); }),
            "--size abc is invalid: expected a finite number");
  // 1e-4 m over 1e9 cells would be a spacing below the smallest length.
  EXPECT_NE(refusal([] {
              grid_from_text("1000000000", "1e-4", Boundary::free, Flags());
            }).find("the spacing dx = 1e-13 m of --size 1e-4 over --grid 1000000000"),
            std::string::npos);
  const Grid line = grid_from_text("128", "+2e-3", Boundary::free, Flags());
  EXPECT_EQ(line.dimension(), 1);
  EXPECT_DOUBLE_EQ(line.dx(), 2e-3 / 128);
}

TEST(SurfaceOptionsTest, HeightMapFileRefusesTheShapeOptionsAndChecksItsOwn) {
  SurfaceOptions options{.height_map = "map.h5", .grid = "64"};
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--grid cannot be used with --height_map: it applies only to --geometry; the grid and its spacing come "
            "from the file");
  options = {.height_map = "map.h5", .pad = 2.0};
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::periodic, Flags()); }),
            "--pad 2 cannot be combined with --boundary periodic: padding is for free boundaries (a periodic surface "
            "repeats without a margin)");
  options = {.height_map = "map.h5", .pad = 20.0};
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--pad 20 is invalid: the factor must be in [1, 16]");
  options = {.height_map = "map.h5", .dx = 0.0};
  EXPECT_EQ(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }),
            "--dx 0 is invalid: must be positive (m)");
  options = {.height_map = "map.h5", .window = "a,b"};
  EXPECT_NE(refusal([&] { make_surface_choice(options, Boundary::free, Flags()); }).find("--window: "),
            std::string::npos);

  options = {.height_map = "map.h5",
             .dataset = "/h",
             .dx = 1e-6,
             .format = "hdf5",
             .invalid = "fill",
             .detrend = "plane",
             .pad = 2.0};
  const auto file = std::get<HeightMapFile>(make_surface_choice(options, Boundary::free, Flags()));
  EXPECT_EQ(file.path, "map.h5");
  EXPECT_EQ(file.read.dataset, "/h");
  EXPECT_EQ(file.read.format, io::HeightMapFormat::hdf5);
  EXPECT_EQ(file.prepare.invalid, surface::InvalidPoints::fill);
  EXPECT_EQ(file.prepare.detrend, surface::Detrend::plane);
  EXPECT_DOUBLE_EQ(file.prepare.pad_factor, 2.0);
  EXPECT_EQ(file.dx.value_or(0.0), 1e-6);
  EXPECT_FALSE(file.dy.has_value());
}

TEST(SurfaceOptionsTest, SpacingFromTheOptionOrTheFile) {
  HeightMap map;
  map.nx = 4;
  map.ny = 3;
  map.dx = 2e-6;  // the file states dx, not dy
  const HeightMapFile file{.path = "map.h5"};
  HeightMap missing = map;
  try {
    set_spacing(missing, file, Flags());
    ADD_FAILURE() << "accepted";
  } catch (const FileError& error) {
    EXPECT_STREQ(error.what(), "height map map.h5 does not state its spacing dy: pass --dy (m)");
  }
  HeightMap given = map;
  set_spacing(given, {.path = "map.h5", .dy = 3e-6}, Flags());
  EXPECT_EQ(given.dx, 2e-6);
  EXPECT_EQ(given.dy, 3e-6);
  // A file's spacing out of the range of lengths names the option that overrides it.
  HeightMap tiny = map;
  tiny.dx = 1e-30;
  EXPECT_NE(refusal([&] {
              set_spacing(tiny, {.path = "map.h5", .dy = 3e-6}, Flags());
            }).find("the spacing dx = 1e-30 m of height map map.h5 (override it with --dx)"),
            std::string::npos);
  HeightMap profile = map;
  profile.dimension = 1;
  profile.ny = 1;
  EXPECT_EQ(refusal([&] { set_spacing(profile, {.path = "p.txt", .dy = 1e-6}, Flags()); }),
            "--dy does not apply to the 1D profile in p.txt");
  set_spacing(profile, file, Flags());
  EXPECT_EQ(profile.dy, 0.0);
}

}  // namespace
}  // namespace halfspace
