// The lubrication problem builder (lubrication_problem.hpp): the rules the
// program and Python share, each message naming the option as the front end
// spells it, and valid options made into the typed film.
#include "halfspace/lubrication/lubrication_problem.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "halfspace/error.hpp"
#include "support/flag_spelling.hpp"

namespace halfspace::lubrication {
namespace {

using Flags = testing::FlagSpelling;  // a program's spelling ("--name value")
const OptionSpelling kLibrary;
const Flags kFlags;

LubricationProblemOptions rigid_film() {
  LubricationProblemOptions options;
  options.viscosity = 0.1;
  options.entrainment_velocity = std::vector<double>{1.0};
  options.separation = 1e-6;
  return options;
}

LubricationProblemOptions elastic_film() {
  LubricationProblemOptions options = rigid_film();
  options.separation.reset();
  options.force = 1e4;
  options.e_star = 1e11;
  return options;
}

LubricationProblemOptions mixed_film() {
  LubricationProblemOptions options = elastic_film();
  options.mixed = true;
  return options;
}

// The message `make_lubrication_problem` throws for `options` with `spelling`.
std::string refusal(const LubricationProblemOptions& options, const OptionSpelling& spelling) {
  try {
    make_lubrication_problem(options, spelling);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "accepted";
  return {};
}

struct Rule {
  std::string what;
  std::function<void(LubricationProblemOptions&)> change;
  LubricationProblemOptions (*base)();
  std::string library;  // the message's start (or a part) in the library's spelling
  std::string flags;    // and in the program's
};

TEST(LubricationProblemTest, EachRuleIsRefusedNamingTheOptionInBothSpellings) {
  const std::vector<Rule> rules{
      {"two controls", [](auto& o) { o.force = 1.0; }, rigid_film, "give exactly one of separation=M and force=N",
       "give exactly one of --separation M and --force N"},
      {"no control",
       [](auto& o) {
         o.offset = 1e-7;
         o.force.reset();
         o.offset.reset();
       },
       mixed_film, "give exactly one of force=N and offset=M", "give exactly one of --force N and --offset M"},
      {"mixed extras", [](auto& o) { o.contact_friction = 0.1; }, rigid_film,
       "offset, contact_friction, boundary_film, speeds belong to the mixed film: add mixed",
       "--offset, --contact_friction, --boundary_film, --speeds belong to the mixed film: add --mixed"},
      {"no viscosity", [](auto& o) { o.viscosity.reset(); }, rigid_film, "no viscosity given: pass viscosity=PA_S",
       "no viscosity given: pass --viscosity PA_S"},
      {"no entrainment", [](auto& o) { o.entrainment_velocity.reset(); }, rigid_film,
       "no entrainment velocity given: pass entrainment_velocity=UX[,UY]",
       "no entrainment velocity given: pass --entrainment_velocity UX[,UY]"},
      {"three velocity components",
       [](auto& o) {
         o.sliding_velocity = std::vector<double>{1, 2, 3};
       },
       rigid_film, "sliding_velocity has 3 values", "--sliding_velocity has 3 values"},
      {"E* and E1", [](auto& o) { o.e1 = 2e11; }, elastic_film, "e_star cannot be combined with E1",
       "--e_star cannot be combined with --E1"},
      {"incomplete pair",
       [](auto& o) {
         o.e_star.reset();
         o.e1 = 2e11;
         o.nu1 = 0.3;
       },
       elastic_film, "incomplete material: missing E2, nu2", "incomplete material: missing --E2, --nu2"},
      {"bad E*", [](auto& o) { o.e_star = -1.0; }, elastic_film, "e_star=-1 is invalid: must be positive (Pa)",
       "--e_star -1 is invalid: must be positive (Pa)"},
      {"incomplete coating",
       [](auto& o) {
         o.e_star.reset();
         o.layer_thickness = 1e-5;
       },
       elastic_film, "incomplete coated half-space: missing layer_E",
       "incomplete coated half-space: missing --layer_E"},
      {"coating and E*",
       [](auto& o) {
         o.layer_thickness = 1e-5;
         o.layer_e = 1e11;
         o.layer_nu = 0.3;
         o.substrate_e = 2e11;
         o.substrate_nu = 0.3;
       },
       elastic_film, "substrate_nu cannot be combined with e_star", "--substrate_nu cannot be combined with --e_star"},
      {"rigid with a lubricant law", [](auto& o) { o.pressure_viscosity = 2e-8; }, rigid_film,
       "pressure_viscosity need an elastic film: give e_star",
       "--pressure_viscosity need an elastic film: give --e_star"},
      {"rigid with a boundary", [](auto& o) { o.boundary = "periodic"; }, rigid_film, "boundary need an elastic film",
       "--boundary need an elastic film"},
      {"rigid with FFT planning", [](auto& o) { o.fft_planning = "measure"; }, rigid_film,
       "fft_planning need an elastic film", "--fft_planning need an elastic film"},
      {"unknown FFT planning", [](auto& o) { o.fft_planning = "exhaustive"; }, elastic_film,
       "fft_planning='exhaustive': ", "--fft_planning 'exhaustive': "},
      {"mixed without a body", [](auto& o) { o.e_star.reset(); }, mixed_film, "mixed needs an elastic body",
       "--mixed needs an elastic body"},
      {"mixed with a coating",
       [](auto& o) {
         o.e_star.reset();
         o.layer_thickness = 1e-5;
         o.layer_e = 1e11;
         o.layer_nu = 0.3;
         o.substrate_e = 2e11;
         o.substrate_nu = 0.3;
       },
       mixed_film, "mixed takes a homogeneous body: a coating is not supported",
       "--mixed takes a homogeneous body: a coating is not supported"},
      {"mixed at a separation",
       [](auto& o) {
         o.force.reset();
         o.separation = 1e-6;
       },
       mixed_film, "separation is the rigid film's: the mixed film takes force=N or offset=M",
       "--separation is the rigid film's: the mixed film takes --force N or --offset M"},
      {"Stribeck at an offset",
       [](auto& o) {
         o.force.reset();
         o.offset = 1e-7;
         o.speeds = std::vector<double>{1};
       },
       mixed_film, "a Stribeck sweep (speeds) is load controlled: pass force=N",
       "a Stribeck sweep (--speeds) is load controlled: pass --force N"},
      {"EHL at a separation",
       [](auto& o) {
         o.force.reset();
         o.separation = 1e-6;
       },
       elastic_film, "an elastic film (EHL) is load controlled: pass force=N, not separation",
       "an elastic film (EHL) is load controlled: pass --force N, not --separation"},
      {"unknown law", [](auto& o) { o.piezoviscosity = "exponential"; }, elastic_film,
       "piezoviscosity='exponential': ", "--piezoviscosity 'exponential': "},
      {"unknown scheme", [](auto& o) { o.couette_scheme = "third-order"; }, elastic_film,
       "couette_scheme='third-order': ", "--couette_scheme 'third-order': "},
      {"unknown preconditioner", [](auto& o) { o.film_preconditioner = "jacobi"; }, elastic_film,
       "film_preconditioner='jacobi': ", "--film_preconditioner 'jacobi': "},
      {"preconditioner of a mixed film", [](auto& o) { o.film_preconditioner = "sparse-lu"; }, mixed_film,
       "applies to the EHL film without mixed", "applies to the EHL film without --mixed"},
      {"preconditioner of a rigid film", [](auto& o) { o.film_preconditioner = "sparse-lu"; }, rigid_film,
       "film_preconditioner need an elastic film", "--film_preconditioner need an elastic film"},
      {"unknown boundary", [](auto& o) { o.boundary = "open"; }, elastic_film, "boundary: ", "--boundary: "},
      {"Newton steps", [](auto& o) { o.max_iterations = 0; }, elastic_film,
       "max_iterations=0 is invalid: allowed range is 1 to 100000", "--max_iterations 0 is invalid"},
      {"mixed Newton steps", [](auto& o) { o.max_iterations = 100001; }, mixed_film, "max_iterations=100001 is invalid",
       "--max_iterations 100001 is invalid"},
      {"rigid sweeps", [](auto& o) { o.max_iterations = 0; }, rigid_film,
       "max_iterations=0 is invalid: at least 1 sweep", "--max_iterations 0 is invalid: at least 1 sweep"},
      {"rigid tolerance", [](auto& o) { o.tolerance = 2.0; }, rigid_film, "tolerance=2 is invalid",
       "--tolerance 2 is invalid"},
      {"rigid load",
       [](auto& o) {
         o.separation.reset();
         o.force = -1.0;
       },
       rigid_film, "force=-1 is invalid", "--force -1 is invalid"},
      {"EHL load", [](auto& o) { o.force = -1.0; }, elastic_film, "force=-1 is invalid", "--force -1 is invalid"},
      {"shear limit", [](auto& o) { o.eyring_stress = -1.0; }, rigid_film, "eyring_stress=-1 Pa is invalid",
       "--eyring_stress -1 Pa is invalid"},
      {"contact friction", [](auto& o) { o.contact_friction = -1.0; }, mixed_film, "contact_friction=-1 is invalid",
       "--contact_friction -1 is invalid"},
      {"boundary film", [](auto& o) { o.boundary_film = 0.0; }, mixed_film, "boundary_film=0 m is invalid",
       "--boundary_film 0 m is invalid"},
      {"offset",
       [](auto& o) {
         o.force.reset();
         o.offset = 1.0 / 0.0;
       },
       mixed_film, "offset=inf m is invalid", "--offset inf m is invalid"},
  };
  for (const Rule& rule : rules) {
    LubricationProblemOptions options = rule.base();
    rule.change(options);
    EXPECT_NE(refusal(options, OptionSpelling{}).find(rule.library), std::string::npos)
        << rule.what << ": " << refusal(options, OptionSpelling{});
    EXPECT_NE(refusal(options, Flags{}).find(rule.flags), std::string::npos)
        << rule.what << ": " << refusal(options, Flags{});
  }
}

// The body's rule is the library's one (make_body): a film and a contact
// problem refuse the same bad body with the same message, in both spellings.
TEST(LubricationProblemTest, AFilmAndAContactRefuseABadBodyAlike) {
  const auto coated = [](BodyOptions& o) {
    o.layer_thickness = 1e-5;
    o.layer_e = 1e11;
    o.layer_nu = 0.3;
    o.substrate_e = 2e11;
    o.substrate_nu = 0.3;
  };
  const auto pair = [](BodyOptions& o) {
    o.e1 = 2e11;
    o.nu1 = 0.3;
    o.e2 = 1e11;
    o.nu2 = 0.25;
  };
  const std::vector<std::pair<std::string, std::function<void(BodyOptions&)>>> bodies{
      {"incomplete coating", [](BodyOptions& o) { o.layer_e = 1e11; }},
      {"coating and E*",
       [&](BodyOptions& o) {
         coated(o);
         o.e_star = 1e11;
       }},
      {"coating and E1",
       [&](BodyOptions& o) {
         coated(o);
         o.e1 = 2e11;
       }},
      {"layer nu",
       [&](BodyOptions& o) {
         coated(o);
         o.layer_nu = 0.7;
       }},
      {"thickness",
       [&](BodyOptions& o) {
         coated(o);
         o.layer_thickness = -1e-5;
       }},
      {"substrate E",
       [&](BodyOptions& o) {
         coated(o);
         o.substrate_e = 1e16;
       }},
      {"E* and E1",
       [](BodyOptions& o) {
         o.e_star = 1e11;
         o.e1 = 2e11;
       }},
      {"E* negative", [](BodyOptions& o) { o.e_star = -1.0; }},
      {"E* beyond the moduli", [](BodyOptions& o) { o.e_star = 1e16; }},
      {"incomplete pair", [](BodyOptions& o) { o.nu2 = 0.3; }},
      {"E1 zero",
       [&](BodyOptions& o) {
         pair(o);
         o.e1 = 0.0;
       }},
      {"nu2 beyond 0.5",
       [&](BodyOptions& o) {
         pair(o);
         o.nu2 = 0.7;
       }},
      {"E* beyond the moduli from nu near -1",
       [&](BodyOptions& o) {
         pair(o);
         o.e1 = 2e14;
         o.e2 = 2e14;
         o.nu1 = -0.99999999;
         o.nu2 = -0.99999999;
       }},
  };
  const Flags flags;
  for (const auto& [what, change] : bodies) {
    for (const OptionSpelling* spelling : {&kLibrary, static_cast<const OptionSpelling*>(&flags)}) {
      LubricationProblemOptions film = elastic_film();
      film.e_star.reset();
      change(film);
      ProblemOptions contact;
      contact.force = std::vector<double>{1.0};
      change(contact);
      std::string contact_refusal;
      try {
        make_problem(contact, *spelling);
      } catch (const InputError& error) {
        contact_refusal = error.what();
      }
      EXPECT_FALSE(contact_refusal.empty()) << what << ": accepted";
      EXPECT_EQ(refusal(film, *spelling), contact_refusal) << what;
    }
  }
}

TEST(LubricationProblemTest, GridRulesNameTheFlowOptionAndTheSurface) {
  LubricationProblemOptions options = rigid_film();
  options.entrainment_velocity = std::vector<double>{1.0, 2.0};
  options.inlet_pressure = -5.0;
  const LubricationProblem velocity = make_lubrication_problem(options, Flags{});
  try {
    velocity.check_grid(Grid::line(41, 1e-5, Boundary::free), Flags{});
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--entrainment_velocity 2 m/s (y component) is invalid on a 1D grid"),
              std::string::npos)
        << error.what();
  }
  options.entrainment_velocity = std::vector<double>{1.0};
  try {
    make_lubrication_problem(options).check_grid(Grid::line(41, 1e-5, Boundary::free));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("inlet_pressure=-5 Pa is invalid"), std::string::npos) << error.what();
  }
  LubricationProblemOptions barus = elastic_film();
  barus.piezoviscosity = "barus";  // Barus without alpha: the law's rule, on the grid
  try {
    make_lubrication_problem(barus).check_grid(Grid::line(41, 1e-5, Boundary::free));
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("pressure_viscosity=0 1/Pa is invalid"), std::string::npos)
        << error.what();
  }
  // The boundary's options, in both spellings.
  LubricationProblemOptions starved = rigid_film();
  starved.supply_fluid_fraction = 1.5;
  const Grid profile = Grid::line(41, 1e-5, Boundary::free);
  const Grid map = Grid::plane(9, 9, 1e-5, 1e-5, Boundary::free);
  LubricationProblemOptions along_x = rigid_film();
  along_x.periodic_x = true;
  LubricationProblemOptions both = along_x;
  both.periodic_y = true;
  const std::vector<std::tuple<LubricationProblemOptions, Grid, std::string, std::string>> boundaries{
      {starved, profile, "supply_fluid_fraction=1.5 is invalid: allowed range is 0 to 1",
       "--supply_fluid_fraction 1.5 is invalid: allowed range is 0 to 1"},
      {along_x, profile, "periodic_x on a 1D grid: the film is periodic along every axis",
       "--periodic_x on a 1D grid: the film is periodic along every axis"},
      {both, map, "periodic_x with periodic_y: the film is periodic along every axis",
       "--periodic_x with --periodic_y: the film is periodic along every axis"},
  };
  for (const auto& [given, grid, library, flags] : boundaries) {
    for (const auto& [spelling, expected] :
         std::vector<std::pair<const OptionSpelling*, std::string>>{{&kLibrary, library}, {&kFlags, flags}}) {
      try {
        make_lubrication_problem(given, *spelling).check_grid(grid, *spelling);
        ADD_FAILURE() << expected << ": accepted";
      } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
      }
    }
  }
  // Periodic along x with fixed sides is a film.
  EXPECT_NO_THROW(make_lubrication_problem(along_x).check_grid(map));

  const LubricationProblem mixed = make_lubrication_problem(mixed_film());
  // Beyond the dense path's nodes and on 2D grids the mixed film takes GMRES.
  EXPECT_NO_THROW(mixed.check_grid(Grid::line(kMaxMixedFilmNodes, 1e-6, Boundary::free)));
  EXPECT_NO_THROW(mixed.check_grid(Grid::line(kMaxMixedFilmNodes + 1, 1e-6, Boundary::free)));
  EXPECT_NO_THROW(mixed.check_grid(Grid::plane(64, 64, 1e-6, 1e-6, Boundary::free)));
}

// What to try where a film did not converge names the options that help, in
// the front end's spelling, with the solver settings in force.
TEST(LubricationProblemTest, FailureHintNamesWhatToTry) {
  const auto contains_all = [](const std::string& hint, std::initializer_list<std::string_view> parts) {
    for (const std::string_view part : parts) EXPECT_NE(hint.find(part), std::string::npos) << part << " in " << hint;
  };
  LubricationProblemOptions rigid = rigid_film();
  rigid.max_iterations = 5000;
  contains_all(make_lubrication_problem(rigid).failure_hint(kFlags),
               {"to try: more --max_iterations (now 5000) or a looser --tolerance (now 1e-11)"});
  LubricationProblemOptions ehl = elastic_film();
  ehl.tolerance = 1e-7;
  const std::string elastic = make_lubrication_problem(ehl).failure_hint(kFlags);
  contains_all(elastic, {"a faster --entrainment_velocity or a smaller --force", "more --max_iterations (now 100)",
                         "a looser --tolerance (now 1e-07)", "--film_preconditioner sparse-lu"});
  EXPECT_EQ(elastic.find("--speeds"), std::string::npos);  // the EHL film has no sweep
  contains_all(
      make_lubrication_problem(mixed_film()).failure_hint(kFlags),
      {"--speeds from a faster speed down to this one", "a smaller --force", "more --max_iterations (now 200)"});
  contains_all(make_lubrication_problem(mixed_film()).failure_hint(kLibrary), {"speeds from", "smaller force"});
  LubricationProblemOptions offset = mixed_film();
  offset.force.reset();
  offset.offset = -1e-7;
  const std::string by_offset = make_lubrication_problem(offset).failure_hint(kFlags);
  contains_all(by_offset, {"a larger --offset", "a faster --entrainment_velocity"});
  EXPECT_EQ(by_offset.find("--speeds"), std::string::npos);  // a sweep is load controlled
}

TEST(LubricationProblemTest, ValidOptionsMakeTheTypedFilm) {
  LubricationProblemOptions rigid = rigid_film();
  rigid.entrainment_velocity = std::vector<double>{1.0, 0.5};
  rigid.sliding_velocity = std::vector<double>{0.2};
  rigid.inlet_pressure = 1e5;
  rigid.side_pressure = 2e5;
  rigid.periodic_x = true;
  rigid.supply_fluid_fraction = 0.5;
  rigid.tolerance = 1e-9;
  rigid.max_iterations = 5000;
  rigid.limiting_shear_stress = 1e6;
  const LubricationProblem film = make_lubrication_problem(rigid);
  EXPECT_EQ(film.kind, FilmKind::rigid);
  EXPECT_EQ(film.separation, 1e-6);
  EXPECT_FALSE(film.load_control);
  EXPECT_EQ(film.conditions.viscosity, 0.1);
  EXPECT_EQ(film.conditions.entrainment_velocity, (std::array<double, 2>{1.0, 0.5}));
  EXPECT_EQ(film.conditions.sliding_velocity, (std::array<double, 2>{0.2, 0.0}));
  EXPECT_EQ(film.conditions.boundary.x, AxisBoundary::periodic);
  EXPECT_EQ(film.conditions.boundary.y, AxisBoundary::fixed_pressure);
  EXPECT_EQ(film.conditions.boundary.x_low_pressure, 1e5);
  EXPECT_EQ(film.conditions.boundary.x_high_pressure, 0.0);
  EXPECT_EQ(film.conditions.boundary.y_low_pressure, 2e5);
  EXPECT_EQ(film.conditions.boundary.y_high_pressure, 2e5);
  EXPECT_EQ(film.conditions.boundary.supply_fluid_fraction, 0.5);
  EXPECT_EQ(film.cavitation.tolerance, 1e-9);
  EXPECT_EQ(film.cavitation.max_iterations, 5000);
  EXPECT_EQ(film.limits.limiting_shear_stress, 1e6);

  LubricationProblemOptions pair = elastic_film();
  pair.e_star.reset();
  pair.e1 = 2e11;
  pair.nu1 = 0.3;
  pair.e2 = 2e11;
  pair.nu2 = 0.3;
  pair.pressure_viscosity = 2e-8;
  pair.boundary = "periodic";
  pair.couette_scheme = "second-order";
  pair.film_preconditioner = "sparse-lu";
  pair.fft_planning = "patient";
  pair.max_iterations = 30;
  const LubricationProblem ehl = make_lubrication_problem(pair);
  EXPECT_EQ(ehl.kind, FilmKind::elastic);
  EXPECT_DOUBLE_EQ(ehl.e_star, 2e11 / (2.0 * (1.0 - 0.09)));
  EXPECT_EQ(ehl.boundary, Boundary::periodic);
  EXPECT_EQ(ehl.laws.piezoviscosity, Piezoviscosity::barus);  // alpha without a law: Barus
  EXPECT_EQ(ehl.laws.pressure_viscosity, 2e-8);
  EXPECT_EQ(ehl.laws.compressibility, Compressibility::dowson_higginson);
  EXPECT_EQ(ehl.elastic.load, 1e4);
  EXPECT_EQ(ehl.elastic.max_iterations, 30);
  EXPECT_EQ(ehl.elastic.couette_scheme, CouetteScheme::second_order);
  EXPECT_EQ(ehl.elastic.preconditioner, KrylovPreconditioner::sparse_lu);
  EXPECT_EQ(make_lubrication_problem(elastic_film()).elastic.preconditioner, KrylovPreconditioner::multigrid);
  EXPECT_EQ(ehl.fft_planning, FftPlanning::patient);
  EXPECT_EQ(make_lubrication_problem(elastic_film()).fft_planning, FftPlanning::estimate);

  LubricationProblemOptions coated = elastic_film();
  coated.e_star.reset();
  coated.layer_thickness = 1e-5;
  coated.layer_e = 7e10;
  coated.layer_nu = 0.3;
  coated.substrate_e = 2.1e11;
  coated.substrate_nu = 0.3;
  coated.compressibility = "none";
  const LubricationProblem layered = make_lubrication_problem(coated);
  ASSERT_TRUE(layered.coating);
  EXPECT_DOUBLE_EQ(layered.e_star, 7e10 / (1.0 - 0.09));
  EXPECT_EQ(layered.laws.compressibility, Compressibility::none);

  LubricationProblemOptions sweep = mixed_film();
  sweep.contact_friction = 0.12;
  sweep.boundary_film = 2e-9;
  sweep.speeds = std::vector<double>{0.1, 1.0};
  sweep.eyring_stress = 5e6;
  const LubricationProblem mixed = make_lubrication_problem(sweep);
  EXPECT_EQ(mixed.kind, FilmKind::mixed);
  EXPECT_EQ(mixed.mixed.load, 1e4);
  EXPECT_EQ(mixed.mixed.offset, 0.0);
  EXPECT_EQ(mixed.mixed.boundary_film, 2e-9);
  EXPECT_EQ(mixed.mixed.friction.contact_friction, 0.12);
  EXPECT_EQ(mixed.mixed.friction.shear.eyring_stress, 5e6);
  EXPECT_EQ(mixed.speeds, (std::vector<double>{0.1, 1.0}));
}

}  // namespace
}  // namespace halfspace::lubrication
