// The option table of `halfspace solve` (option_table.hpp): one entry per
// option drives the CLI11 registration, the command-line conversion and the
// TOML merge, so the flag names and the config keys cannot drift apart.
#include "solve_options.hpp"

#include <array>
#include <span>

#include "surface_option_table.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

using Kind = OptionKind;
using SolveOption = OptionSpec<SolveOptions>;

constexpr std::string_view kMaterial = "Material (E1, nu1, E2 and nu2, or E-star)";
constexpr std::string_view kCoating = "Coated half-space (all five, instead of the material; the surface is rigid)";
constexpr std::string_view kLoad = "Load (exactly one)";
constexpr std::string_view kInterface = "Interface law";
constexpr std::string_view kSolver = "Solver";
constexpr std::string_view kOutput = "Output";
constexpr std::string_view kStress = "Subsurface stresses (single solves)";
constexpr std::string_view kFriction =
    "Friction (Coulomb; needs E1, nu1, E2, nu2, dissimilar bodies solved coupled; one normal load)";
constexpr std::string_view kAdhesion = "Adhesion (a cohesive law beside the hard wall; --approach may be negative)";

// The rows of solve's own options, after the surface's.
const std::array kOwnOptions{
    SolveOption{"pad", &SolveOptions::pad, Kind::number, kPreparationGroup, "FACTOR",
                "free boundary only: embed the map in a FACTOR times larger grid at its lowest height [1]"},
    SolveOption{"boundary", &SolveOptions::boundary, Kind::text, kGridGroup, "TYPE", "periodic or free [free]"},
    SolveOption{"E1", &SolveOptions::e1, Kind::number, kMaterial, "PA", "Young's modulus of body 1 (Pa)"},
    SolveOption{"nu1", &SolveOptions::nu1, Kind::number, kMaterial, "NU", "Poisson's ratio of body 1"},
    SolveOption{"E2", &SolveOptions::e2, Kind::modulus, kMaterial, "PA",
                "Young's modulus of body 2 (Pa); inf for a rigid body 2"},
    SolveOption{"nu2", &SolveOptions::nu2, Kind::number, kMaterial, "NU", "Poisson's ratio of body 2"},
    SolveOption{"E-star", &SolveOptions::e_star, Kind::number, kMaterial, "PA",
                "composite modulus E* (Pa), instead of E1, nu1, E2, nu2"},
    // Coated half-space (docs/usage.md#coated-half-space).
    SolveOption{"layer-thickness", &SolveOptions::layer_thickness, Kind::number, kCoating, "M",
                "thickness t of the elastic layer bonded to the substrate (m)"},
    SolveOption{"layer-E", &SolveOptions::layer_e, Kind::number, kCoating, "PA", "Young's modulus of the layer (Pa)"},
    SolveOption{"layer-nu", &SolveOptions::layer_nu, Kind::number, kCoating, "NU", "Poisson's ratio of the layer"},
    SolveOption{"substrate-E", &SolveOptions::substrate_e, Kind::number, kCoating, "PA",
                "Young's modulus of the substrate (Pa)"},
    SolveOption{"substrate-nu", &SolveOptions::substrate_nu, Kind::number, kCoating, "NU",
                "Poisson's ratio of the substrate"},
    // Hardness cap (elastic-perfectly plastic surface, docs/theory.md#hardness-cap).
    SolveOption{"hardness", &SolveOptions::hardness, Kind::number, kInterface, "PA",
                "hardness H (Pa): caps the pressure at H, cells at the cap flow plastically (every solver but lemke) "
                "[none: elastic]"},
    SolveOption{"force", &SolveOptions::force, Kind::numbers, kLoad, "F",
                "total normal force: N (2D) or N/m (1D); a list F1,F2,... or a log range START:STOP:COUNT "
                "solves a sweep, each step warm-started from the previous one"},
    SolveOption{"mean-pressure", &SolveOptions::mean_pressure, Kind::numbers, kLoad, "PA",
                "force over the domain area (Pa); a list or START:STOP:COUNT makes a sweep"},
    SolveOption{"approach", &SolveOptions::approach, Kind::numbers, kLoad, "M",
                "imposed rigid-body approach (m): displacement control; a list or START:STOP:COUNT makes a sweep"},
    SolveOption{
        "solver", &SolveOptions::solver, Kind::text, kSolver, "NAME",
        "contact solver: pk-multilevel (pk-fourier started from coarser grids), pk-fourier (Polonsky-Keer with "
        "Fourier preconditioner), pk (plain Polonsky-Keer), "
        "lemke (Lemke pivoting, dense, small grids), lcpquad (the paper's QP, dense, small grids) [pk-multilevel]"},
    SolveOption{"tol", &SolveOptions::tol, Kind::number, kSolver, "X", "relative residual tolerance [1e-10]"},
    SolveOption{"max-iter", &SolveOptions::max_iter, Kind::integer, kSolver, "N", "iteration limit [10000]"},
    SolveOption{"threads", &SolveOptions::threads, Kind::integer, kSolver, "N",
                "threads for loops and FFTs [all cores]"},
    SolveOption{"fft-planning", &SolveOptions::fft_planning, Kind::text, kSolver, "MODE",
                "FFTW planning effort: estimate, measure or patient [measure]"},
    SolveOption{"precision", &SolveOptions::precision, Kind::text, kSolver, "MODE",
                "arithmetic of the Polonsky-Keer solvers: double, or mixed (the step's products and the "
                "preconditioner in single precision; the residual, contact decisions and convergence check in "
                "double; one process, not the dense solvers or adhesion) [double]"},
    SolveOption{"deflation-block", &SolveOptions::deflation_block, Kind::integer, kSolver, "B",
                "coarse-grid correction on B x B blocks of the contact (pk-fourier, pk-multilevel's finest grid; "
                "2D grids whose nx and ny B divides, at least 3 blocks per axis); 0 for none "
                "[32 with pk-multilevel on grids of 2048^2 cells or more where it applies, else none]"},
    SolveOption{"active-set", &SolveOptions::active_set, Kind::text, kSolver, "on|off|automatic",
                "pk-multilevel: begin the finest grid's solve with primal-dual active-set steps (whole-set "
                "updates, each a deflated linear solve on a fixed set), then Polonsky-Keer; 2D grids without "
                "--hardness; automatic: on for periodic grids from 4096^2 cells without a coating, else off "
                "[automatic]"},
    SolveOption{"max-memory", &SolveOptions::max_memory, Kind::memory, kSolver, "SIZE",
                "refuse to start when the run's estimated peak memory exceeds SIZE: bytes, or K, M, G, T (powers of "
                "1024), e.g. 512M or 8G [the memory available: MemAvailable, or a cgroup's limit if lower]"},
    // Subsurface stresses: the /stress group of the result file.
    SolveOption{"stress-depths", &SolveOptions::stress_depths, Kind::text, kStress, "LIST|START:STOP:COUNT",
                "also write the stresses below the contact at these depths (m, > 0): z1,z2,... or COUNT evenly "
                "spaced from START to STOP"},
    SolveOption{"stress-nu", &SolveOptions::stress_nu, Kind::number, kStress, "NU",
                "Poisson's ratio of the body whose stresses are wanted [that body's, from E1, nu1, E2, nu2]"},
    SolveOption{"stress-body", &SolveOptions::stress_body, Kind::text, kStress, "1|2",
                "whose stresses: body 1 takes the shear traction -q, body 2 q [the one that deforms: 1 when coated "
                "or E2 = inf, else 2]"},
    // Adhesion.
    SolveOption{"adhesion", &SolveOptions::adhesion, Kind::text, kAdhesion, "LAW",
                "cohesive law: md (Maugis-Dugdale: stress sigma0 = w/h0 where 0 <= gap < h0) or exponential "
                "(traction -(w/rho) exp(-gap/rho)); solved by the adhesive solver (adhesive-pcg) [none]"},
    SolveOption{"work-of-adhesion", &SolveOptions::work_of_adhesion, Kind::number, kAdhesion, "W",
                "work of adhesion w (J/m^2), required with --adhesion"},
    SolveOption{"adhesion-range", &SolveOptions::adhesion_range, Kind::number, kAdhesion, "M",
                "range of the law (m): h0 for md, rho for exponential; or --adhesion-stress for md"},
    SolveOption{"adhesion-stress", &SolveOptions::adhesion_stress, Kind::number, kAdhesion, "PA",
                "md only: the Dugdale stress sigma0 (Pa) instead of --adhesion-range (h0 = w / sigma0)"},
    SolveOption{"adhesion-precondition", &SolveOptions::adhesion_precondition, Kind::text, kAdhesion, "on|off",
                "on: the adhesive solver runs conjugate gradients preconditioned by the compliance (adhesive-pcg); "
                "off: spectral projected gradients (adhesive-spg, 5-15x slower; docs/solvers.md) [on]"},
    // Friction (docs/usage.md#friction).
    SolveOption{"friction", &SolveOptions::friction, Kind::number, kFriction, "MU",
                "Coulomb friction coefficient mu (>= 0): solve the shear tractions, stick and slip under "
                "--tangential-force, --tangential-displacement or --sliding"},
    SolveOption{"tangential-force", &SolveOptions::tangential_force_text, Kind::text, kFriction, "QX[,QY][;...]",
                "tangential force that body 1 exerts on body 2: N (2D) or N/m (1D, x only); several steps "
                "separated by ';' (quote them), or START:STOP:COUNT evenly spaced (each end QX or QX,QY), make a "
                "history applied in order, each step from the previous state"},
    SolveOption{"tangential-displacement", &SolveOptions::tangential_displacement_text, Kind::text, kFriction,
                "DX[,DY][;...]",
                "tangential rigid-body displacement of body 1 against body 2 (m); steps and ranges as "
                "--tangential-force"},
    SolveOption{"sliding", &SolveOptions::sliding, Kind::numbers, kFriction, "X,Y",
                "gross sliding along the direction (X, Y): every contact cell at |q| = mu p, total force mu P"},
    SolveOption{"tangential-tol", &SolveOptions::tangential_tol, Kind::number, kFriction, "X",
                "tolerance of the tangential solver's residual (the duality gap of Coulomb's law) [1e-6]"},
    SolveOption{"tangential-max-iter", &SolveOptions::tangential_max_iter, Kind::integer, kFriction, "N",
                "iteration limit of each tangential step [10000]"},
    SolveOption{"tangential-release-period", &SolveOptions::tangential_release_period, Kind::integer, kFriction, "N",
                "tangential conjugate gradients: slipping cells whose slip turned back inward return to the stick "
                "set only every N iterations, held on their circle between (1: every iteration) [5]"},
    SolveOption{"tangential-active-set", &SolveOptions::tangential_active_set, Kind::integer, kFriction, "N",
                "tangential step: at most N semi-smooth Newton updates of the stick/slip sets and slip directions "
                "(conjugate gradients on the frozen sets between) before the conjugate gradients finish (0: none) "
                "[0]"},
    SolveOption{"tangential-coarse-start", &SolveOptions::tangential_coarse_start, Kind::text, kFriction,
                "on|off|automatic",
                "tangential step: solve it first on grids of twice, four times, ... the spacing and start from the "
                "prolonged traction (serial solves of similar bodies on grids that halve); automatic: on wherever "
                "it applies [automatic]"},
    SolveOption{"no-coupling", &SolveOptions::no_coupling, Kind::flag, kFriction, "",
                "dissimilar bodies (Dundurs' beta != 0): ignore the normal-tangential coupling (the pressure of the "
                "frictionless solve, for comparison); by default the coupled problem is solved"},
    SolveOption{"normal-load-steps", &SolveOptions::normal_load_steps, Kind::integer, kFriction, "N",
                "coupled friction: apply the normal load in N equal increments at zero tangential load before the "
                "tangential steps (the shear it leaves depends on the path) [1]"},
    SolveOption{"output", &SolveOptions::output, Kind::path, kOutput, "FILE",
                "result file (HDF5), required; replaced if it exists"},
    SolveOption{"quiet", &SolveOptions::quiet, Kind::flag, kOutput, "",
                "print nothing unless there is an error (no summary, no progress line)"},
    SolveOption{"plot", &SolveOptions::plot, Kind::flag, kOutput, "",
                "draw PNG figures next to the output with scripts/halfspace_plot.py (maps; sweep curves)"},
};
const std::array kOptions = joined(surface_option_table<SolveOptions>(), kOwnOptions);

// Options that exclude each other (Alternative, option_table.hpp): the
// surface is chosen only by its selectors, so `--grid` alone must not silently
// drop a file's height map, it must be reported as a conflict.
const std::vector<AlternativeGroup> kAlternatives{
    {{{"force"}, {"force"}}, {{"mean-pressure"}, {"mean-pressure"}}, {{"approach"}, {"approach"}}},
    {{{"E-star"}, {"E-star"}},
     {{"E1", "nu1", "E2", "nu2"}, {"E1", "nu1", "E2", "nu2"}},
     {{"layer-thickness", "layer-E", "layer-nu", "substrate-E", "substrate-nu"},
      {"layer-thickness", "layer-E", "layer-nu", "substrate-E", "substrate-nu"}}},
    {{{"tangential-force"}, {"tangential-force"}},
     {{"tangential-displacement"}, {"tangential-displacement"}},
     {{"sliding"}, {"sliding"}}},
    {{{"height-map"},
      {"height-map", "dataset", "dx", "dy", "format", "unit", "window", "invalid", "detrend", "resample", "pad"}},
     {{"geometry"}, {"geometry", "radius", "wavelength", "amplitude", "grid", "size"}}},
};

}  // namespace

void add_solve_options(CLI::App& solve) {
  add_config_option(solve, "E-star = 1e11");
  add_options(solve, std::span<const SolveOption>(kOptions));
}

SolveOptions solve_options_from_command_line(const CLI::App& solve, const std::vector<std::string>& argv) {
  SolveOptions options;
  read_command_line(solve, argv, bind_options(std::span<const SolveOption>(kOptions), options), options);
  return options;
}

void merge_config_file(SolveOptions& options) {
  merge_config_file(bind_options(std::span<const SolveOption>(kOptions), options), kAlternatives, "solve", options);
}

ProblemOptions problem_options(const SolveOptions& options) {
  ProblemOptions problem = options;
  if (problem.adhesion) problem.adhesion_tol = problem.tol;
  if (options.tangential_force_text) {
    problem.tangential_force =
        parse_tangential_steps(*options.tangential_force_text, options.describe("tangential-force"));
  }
  if (options.tangential_displacement_text) {
    problem.tangential_displacement =
        parse_tangential_steps(*options.tangential_displacement_text, options.describe("tangential-displacement"));
  }
  if (options.no_coupling) problem.coupling = "off";
  return problem;
}

FlagSpelling::FlagSpelling(const SolveOptions& options)
    : GivenSpelling(options, std::span<const SolveOption>(kOptions)) {}

std::string FlagSpelling::key(std::string_view option) const {
  if (option == "adhesion_tol") return "tol";
  if (option == "coupling") return "no-coupling";
  return GivenSpelling::key(option);
}

}  // namespace halfspace::app
