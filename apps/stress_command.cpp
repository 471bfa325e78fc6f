// The stress command: result file -> pressure and grid -> stress volume ->
// stress file. Options are read as text and parsed strictly, as solve's are.
#include "stress_command.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "activity.hpp"
#include "exit_codes.hpp"
#include "halfspace/error.hpp"
#include "halfspace/io/output_file.hpp"
#include "halfspace/io/result_pressure_reader.hpp"
#include "halfspace/io/stress_writer.hpp"
#include "halfspace/io/xdmf_writer.hpp"
#include "halfspace/memory_estimate.hpp"
#include "halfspace/physical_ranges.hpp"
#include "halfspace/stress/stress_volume.hpp"
#include "halfspace/stress/stressed_body.hpp"
#include "halfspace/stress/subsurface_stress.hpp"
#include "halfspace/threads.hpp"
#include "halfspace/version.hpp"
#include "memory_check.hpp"
#include "option_table.hpp"
#include "processes.hpp"
#include "value_parsing.hpp"

namespace halfspace::app {
namespace {

struct StressOptions {
  std::string result;
  std::optional<std::string> depths;
  std::optional<std::string> depth_range;
  std::optional<std::string> nu;
  std::optional<std::string> body;
  std::optional<std::string> output;
  std::optional<std::string> max_memory;
  std::optional<std::string> threads;
  bool quiet = false;
};

int threads_from(const std::optional<std::string>& text) {
  if (!text) return default_threads();
  const long long threads = parse_integer(*text, fmt::format("--threads {}", *text));
  if (threads < 1 || threads > max_threads()) {
    throw InputError(fmt::format("--threads {} is invalid: allowed range is 1 to {} threads", *text, max_threads()));
  }
  return static_cast<int>(threads);
}

// The stresses of `place`'s result at `depths` into the stress file, after
// checking the options against the result (every process alike).
int stresses_at(StressPlace& place, const StressOptions& o, const std::vector<double>& depths,
                const std::vector<std::string>& argv) {
  const std::optional<double> given_nu = o.nu ? std::optional(parse_stress_poisson_ratio(*o.nu, "--nu")) : std::nullopt;
  const std::string& output = *o.output;
  io::ResultPressure& input = place.input;
  const Grid& grid = input.grid;
  // The spacings SI lengths may take (physical_ranges.hpp): beyond them the
  // stress coefficients overflow.
  require_in_range(fmt::format("result file '{}': root attribute dx = {:.6g} m", o.result, grid.dx()), grid.dx(),
                   kMinLength, kMaxLength, "m");
  if (grid.dimension() == 2) {
    require_in_range(fmt::format("result file '{}': root attribute dy = {:.6g} m", o.result, grid.dy()), grid.dy(),
                     kMinLength, kMaxLength, "m");
  }
  in_context(o.depths ? fmt::format("--depths {}", *o.depths) : fmt::format("--depth-range {}", *o.depth_range),
             [&] { stress::check_depths(grid, depths); });
  const std::optional<LayeredMaterial>& coating = input.coating;
  if (coating) {
    in_context(fmt::format("{} is a coated half-space's result", o.result),
               [&] { stress::require_coated_stress_grid(grid, *coating); });
  }
  // Whose stresses (the file's bodies or coating give the default and the
  // Poisson's ratio, stress/stressed_body.hpp).
  const std::optional<stress::StressedBody> requested =
      o.body ? std::optional(stress::parse_stressed_body(*o.body, "--body")) : std::nullopt;
  std::optional<ElasticPair> bodies;
  if (coating) {
    bodies = ElasticPair::coated(*coating);
  } else if (input.bodies) {
    bodies = ElasticPair((*input.bodies)[0], (*input.bodies)[1]);
  }
  const stress::StressedBodyChoice body = in_context(fmt::format("result file '{}'", o.result), [&] {
    return stress::choose_stressed_body(requested, given_nu, bodies, "--body", "--nu");
  });
  const bool shear = input.has_shear();
  // On several processes each holds its share of the fields and transforms
  // (the first process has read the whole result besides, and freed it).
  const double share = static_cast<double>(input.pressure.size()) / static_cast<double>(grid.size());
  const double estimate = stress_command_memory_estimate(grid, coating.has_value(), shear, share);
  const std::string what = o.max_memory ? fmt::format("--max-memory {}", *o.max_memory) : "--max-memory";
  place.agree([&] {
    require_memory(fmt::format("stresses on the {} grid of {} (the transforms and one depth's 9 fields of {} cells "
                               "x 8 bytes at a time{})",
                               grid.shape_string(), o.result, grid.size(), share < 1.0 ? ", per process" : ""),
                   estimate, memory_limit(o.max_memory, what));
  });

  stress::VonMisesMaximum maximum;
  {
    const Activity activity(fmt::format("computing stresses at {} depths on the {} grid and writing {}", depths.size(),
                                        grid.shape_string(), output));
    const std::unique_ptr<stress::SubsurfaceStress> stresses =
        stress::make_subsurface_stress(grid, coating, body, place.layout);
    // Body 1 (a coated result's body, ElasticPair::coated) takes the
    // traction on it, -q of the file's /shear_x, /shear_y.
    std::array<std::vector<double>, 2> body1_shear;
    const stress::SurfaceTractions tractions =
        stress::tractions_on(body.body, {input.pressure, input.shear_x, input.shear_y}, body1_shear);
    maximum = place.write_file(output, *stresses, tractions, depths, {o.result, join_command_line(argv)});
  }
  if (!o.quiet && place.first) {
    const auto row = [](std::string_view label, const std::string& value) {
      fmt::print("  {:<15} {}\n", label, value);
    };
    fmt::print("halfspace {} ({}) stress\n", kVersion, kGitHash);
    row("result", o.result);
    row("grid", coating ? fmt::format("{} ({}), coated: layer t = {:.6g} m, nu1 = {}; substrate nu2 = {}",
                                      grid.shape_string(), to_string(grid.boundary()), coating->thickness,
                                      coating->layer.poissons_ratio, coating->substrate.poissons_ratio)
                        : fmt::format("{} ({}), body {}, Poisson's ratio {}", grid.shape_string(),
                                      to_string(grid.boundary()), stress::body_number(body.body), body.poisson_ratio));
    row("tractions", shear ? "pressure and shear (/shear_x, /shear_y)" : "pressure");
    row("depths", fmt::format("{} from {:.6g} m to {:.6g} m", depths.size(), depths.front(), depths.back()));
    const auto& m = maximum;
    row("max von Mises", fmt::format("{:.6g} Pa at x = {:.6g} m, y = {:.6g} m, z = {:.6g} m", m.value, m.x, m.y, m.z));
    row("output", output);
  }
  return kExitOk;
}

int run_stress(const StressOptions& o, const std::vector<std::string>& argv) {
  // A coated result brings each body's Poisson's ratio; --nu is checked
  // against the file once it is read.
  if (o.nu) parse_stress_poisson_ratio(*o.nu, "--nu");
  const std::vector<double> depths =
      parse_stress_depths(o.depths ? &*o.depths : nullptr, o.depth_range ? &*o.depth_range : nullptr);
  if (!o.output) throw InputError("no output file given: pass --output FILE.h5");
  const std::string& output = *o.output;
  if (io::same_file(output, o.result)) {
    throw InputError(
        fmt::format("--output {} is the input result file: the stresses go to a new file, pass "
                    "another --output",
                    output));
  }
  io::check_output_path(output);
  io::check_xdmf_sidecar_path(output);
  set_threads(threads_from(o.threads));

  return run_stress_everywhere(o.result, [&](StressPlace& place) { return stresses_at(place, o, depths, argv); });
}

}  // namespace

double parse_stress_poisson_ratio(const std::string& text, std::string_view option) {
  const std::string what = fmt::format("{} {}", option, text);
  const double nu = parse_number(text, what);
  if (!(nu > -1.0 && nu <= 0.5)) throw InputError(fmt::format("{} is invalid: allowed range is -1 < nu <= 0.5", what));
  return nu;
}

std::vector<double> parse_depth_list(std::string_view text, const std::string& what) {
  std::vector<double> values;
  std::string_view rest = text;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view part = rest.substr(0, comma);
    values.push_back(parse_number(part, fmt::format("{} (the part '{}')", what, part)));
    if (values.size() > stress::kMaxDepthCount) {
      throw InputError(fmt::format("{} is invalid: it gives more than {} depths", what, stress::kMaxDepthCount));
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  for (const double z : values) {
    if (!(z > 0.0)) throw InputError(fmt::format("{} is invalid: every depth must be > 0 m, got {:.6g}", what, z));
  }
  stress::check_depths(values);
  return values;
}

std::vector<double> parse_depth_range(const std::string& text, const std::string& what) {
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos) {
    throw InputError(fmt::format("{} is invalid: expected START:STOP:COUNT, e.g. 1e-6:2e-5:20", what));
  }
  const double start = parse_number(text.substr(0, first), what);
  const double stop = parse_number(text.substr(first + 1, second - first - 1), what);
  const long long count = parse_integer(text.substr(second + 1), what);
  if (count < 1 || count > static_cast<long long>(stress::kMaxDepthCount)) {
    throw InputError(fmt::format("{} is invalid: COUNT = {} is outside the allowed range 1 to {}", what, count,
                                 stress::kMaxDepthCount));
  }
  if (!(start > 0.0) || !(stop >= start) || (count > 1 && !(stop > start))) {
    throw InputError(fmt::format("{} is invalid: need 0 < START < STOP (m) (START = STOP only with COUNT 1)", what));
  }
  std::vector<double> values;
  for (long long k = 0; k < count; ++k) {
    values.push_back(count == 1 ? start
                                : start + (stop - start) * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  stress::check_depths(values);
  return values;
}

std::vector<double> parse_stress_depths(const std::string* depths, const std::string* depth_range) {
  if (depths && depth_range) throw InputError("--depths and --depth-range were both given: pass one of them");
  if (!depths && !depth_range) {
    throw InputError("no depth given: pass --depths z1,z2,... or --depth-range START:STOP:COUNT (m, > 0)");
  }
  return depths ? parse_depth_list(*depths, fmt::format("--depths {}", *depths))
                : parse_depth_range(*depth_range, fmt::format("--depth-range {}", *depth_range));
}

Command add_stress_command(CLI::App& program) {
  CLI::App* command =
      program.add_subcommand("stress", "Compute the subsurface stress field of a solved contact from its result file");
  command->footer(
      "Stresses in Pa, tension positive (compression negative), z positive downwards; a friction result's shear "
      "tractions (/shear_x, /shear_y) are applied beside the pressure; see docs/usage.md#stress.");
  auto o = std::make_shared<StressOptions>();
  command->add_option("RESULT", o->result, "a result file of `halfspace solve` (HDF5)")->required();
  command->add_option("--depths", o->depths, "depths below the surface z1,z2,... (m, > 0)")->type_name("LIST");
  command->add_option("--depth-range", o->depth_range, "COUNT depths evenly spaced from START to STOP (m)")
      ->type_name("START:STOP:COUNT");
  command
      ->add_option("--nu", o->nu,
                   "Poisson's ratio of the body whose stresses are wanted, -1 < NU <= 0.5 (required, except for "
                   "a result that records its bodies or coating)")
      ->type_name("NU");
  command
      ->add_option("--body", o->body,
                   "whose stresses: body 1 takes the shear traction -q, body 2 q [the one that deforms: 1 for a "
                   "coated result or a rigid body 2, else 2]")
      ->type_name("1|2");
  command->add_option("--output", o->output, "the stress file (HDF5), required; replaced if it exists")
      ->type_name("FILE");
  command->add_option("--max-memory", o->max_memory, "refuse to start above this estimated peak memory [available]")
      ->type_name("SIZE");
  command->add_option("--threads", o->threads, "threads for the transforms and loops [the CPUs available]")
      ->type_name("N");
  command->add_flag("--quiet", o->quiet, "print nothing unless there is an error");
  return {command, [o](const std::vector<std::string>& argv) { return run_stress(*o, argv); }};
}

}  // namespace halfspace::app
