// A Stribeck curve: the mixed film over entrainment speeds at one load, each
// solve warm-started from the last (mixed_film.hpp), on one process or with
// the speeds shared out among several.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <utility>

#include "halfspace/error.hpp"
#include "halfspace/lubrication/mixed_film.hpp"
#include "mixed_film_grid_sequence.hpp"

namespace halfspace::lubrication {

namespace {

// Checks the sweep's input (every process alike).
void check_sweep(const FlowConditions& conditions, const MixedFilmOptions& options, const std::vector<double>& speeds) {
  options.validate();
  if (!options.load_controlled()) throw InputError("a Stribeck sweep is load controlled: give the mixed film a load");
  const std::array<double, 2>& u = conditions.entrainment_velocity;
  const double speed = std::hypot(u[0], u[1]);
  if (!(speed > 0.0)) throw InputError("a Stribeck sweep needs a nonzero entrainment velocity (its direction)");
  if (speeds.empty()) throw InputError("a Stribeck sweep needs at least one speed");
  for (const double s : speeds) {
    if (!(std::isfinite(s) && s > 0.0)) {
      throw OptionError("speeds", format_number(s) + " m/s", "is invalid: speeds must be positive and finite");
    }
  }
}

// The Hersey number eta0 s / w' at speed s, w' the load per unit width
// across the entrainment.
double hersey_number(const Grid& grid, const FlowConditions& conditions, const MixedFilmOptions& options, double s) {
  const std::array<double, 2>& u = conditions.entrainment_velocity;
  const double width = grid.dimension() == 1              ? 1.0
                       : std::abs(u[0]) >= std::abs(u[1]) ? static_cast<double>(grid.ny()) * grid.dy()
                                                          : static_cast<double>(grid.nx()) * grid.dx();
  return conditions.viscosity * s / (options.load / width);
}

// Solves speeds[first, end) in order, each from the last converged film;
// a point that fails from it is solved again without a start, as alone
// (grid sequencing and the faster films' way down): on the measured map's
// 64^2 window the way up from 2.8e-4 to 4e-4 m/s stalls in the transition
// band where the way down converges (docs/development-log.md, 2026-12-02,
// thirtieth session). Its iterations count both solves.
void sweep_run(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
               const LubricantLaws& laws, const MixedFilmOptions& options, const std::vector<double>& speeds,
               std::size_t first, std::size_t end, std::vector<StribeckPoint>& points) {
  const std::array<double, 2>& u = conditions.entrainment_velocity;
  const double speed = std::hypot(u[0], u[1]);
  // The grids' dry contacts, the same at every speed, solved once; one
  // GMRES basis.
  detail::MixedFilmKeep keep;
  for (std::size_t k = first; k < end; ++k) {
    const double s = speeds[k];
    StribeckPoint& point = points[k];
    point.entrainment_speed = s;
    point.hersey_number = hersey_number(op.grid(), conditions, options, s);
    const MixedFilm* previous = k > first && points[k - 1].film.converged() ? &points[k - 1].film : nullptr;
    const FlowConditions at = detail::at_speed_factor(conditions, s / speed);
    point.film = detail::solve_mixed_film(op, gap, keep, at, laws, options, previous);
    if (point.film.converged() || previous == nullptr) continue;
    MixedFilm alone = detail::solve_mixed_film(op, gap, keep, at, laws, options);
    alone.iterations += point.film.iterations;
    alone.krylov_iterations += point.film.krylov_iterations;
    if (!alone.converged()) alone.message = point.film.message + "; solved alone: " + alone.message;
    point.film = std::move(alone);
  }
}

// A point's summary as numbers, in the order summary_from reads them.
constexpr std::size_t kSummaryValues = 17;
void summary_into(const StribeckPoint& point, std::span<double> out) {
  const MixedFilm& f = point.film;
  const double values[kSummaryValues] = {static_cast<double>(f.status),
                                         static_cast<double>(f.iterations),
                                         static_cast<double>(f.krylov_iterations),
                                         static_cast<double>(f.line_search_halvings),
                                         f.load,
                                         f.fluid_load,
                                         f.contact_load,
                                         f.fluid_friction_force[0],
                                         f.fluid_friction_force[1],
                                         f.contact_friction_force[0],
                                         f.contact_friction_force[1],
                                         f.friction_coefficient,
                                         f.contact_load_fraction,
                                         f.contact_area_fraction,
                                         f.central_film_thickness,
                                         f.minimum_film_thickness,
                                         f.max_pressure};
  std::copy(std::begin(values), std::end(values), out.begin());
}
void summary_from(std::span<const double> in, MixedFilm& f) {
  f.status = static_cast<FilmStatus>(static_cast<int>(in[0]));
  f.iterations = static_cast<int>(in[1]);
  f.krylov_iterations = static_cast<int>(in[2]);
  f.line_search_halvings = static_cast<int>(in[3]);
  f.load = in[4];
  f.fluid_load = in[5];
  f.contact_load = in[6];
  f.fluid_friction_force = {in[7], in[8]};
  f.contact_friction_force = {in[9], in[10]};
  f.friction_coefficient = in[11];
  f.contact_load_fraction = in[12];
  f.contact_area_fraction = in[13];
  f.central_film_thickness = in[14];
  f.minimum_film_thickness = in[15];
  f.max_pressure = in[16];
}

}  // namespace

std::pair<std::size_t, std::size_t> stribeck_run(std::size_t speeds, int rank, int size) {
  // Runs in speed order go to the processes from the last to the first.
  const auto share = static_cast<std::size_t>(size - 1 - rank);
  const auto processes = static_cast<std::size_t>(size);
  return {share * speeds / processes, (share + 1) * speeds / processes};
}

std::vector<StribeckPoint> stribeck_sweep(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                          const FlowConditions& conditions, const LubricantLaws& laws,
                                          const MixedFilmOptions& options, const std::vector<double>& speeds) {
  check_sweep(conditions, options, speeds);
  std::vector<StribeckPoint> points(speeds.size());
  sweep_run(op, gap, conditions, laws, options, speeds, 0, speeds.size(), points);
  return points;
}

std::vector<StribeckPoint> stribeck_sweep(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                          const FlowConditions& conditions, const LubricantLaws& laws,
                                          const MixedFilmOptions& options, const std::vector<double>& speeds,
                                          const linalg::Communicator& processes) {
  check_sweep(conditions, options, speeds);
  const std::size_t m = speeds.size();
  std::vector<StribeckPoint> points(m);
  const auto [first, end] = stribeck_run(m, processes.rank(), processes.size());
  sweep_run(op, gap, conditions, laws, options, speeds, first, end, points);
  if (processes.size() == 1) return points;
  // The summaries and the messages' lengths: each process fills its own
  // points', the sum over the processes (the others hold zeros) is exact.
  std::vector<double> summaries(m * (kSummaryValues + 1), 0.0);
  std::size_t bytes = 0;
  for (std::size_t k = first; k < end; ++k) {
    summary_into(points[k], std::span<double>(summaries).subspan(k * (kSummaryValues + 1), kSummaryValues));
    summaries[k * (kSummaryValues + 1) + kSummaryValues] = static_cast<double>(points[k].film.message.size());
    bytes += points[k].film.message.size();
  }
  processes.sum(summaries);
  const auto length = [&](std::size_t k) {
    return static_cast<std::size_t>(summaries[k * (kSummaryValues + 1) + kSummaryValues]);
  };
  // The messages, each process's in speed order, the processes in rank order.
  std::string mine;
  mine.reserve(bytes);
  for (std::size_t k = first; k < end; ++k) mine += points[k].film.message;
  std::size_t total = 0;
  for (std::size_t k = 0; k < m; ++k) total += length(k);
  std::string all(total, '\0');
  processes.concatenate(std::as_bytes(std::span<const char>(mine.data(), mine.size())),
                        std::as_writable_bytes(std::span<char>(all.data(), all.size())), 1);
  std::size_t offset = 0;
  for (int rank = 0; rank < processes.size(); ++rank) {
    const auto [run_first, run_end] = stribeck_run(m, rank, processes.size());
    for (std::size_t k = run_first; k < run_end; ++k) {
      if (k < first || k >= end) {
        StribeckPoint& point = points[k];
        point.entrainment_speed = speeds[k];
        point.hersey_number = hersey_number(op.grid(), conditions, options, speeds[k]);
        summary_from(std::span<const double>(summaries).subspan(k * (kSummaryValues + 1), kSummaryValues), point.film);
        point.film.entrainment_speed = speeds[k];
        point.film.message = all.substr(offset, length(k));
      }
      offset += length(k);
    }
  }
  return points;
}

}  // namespace halfspace::lubrication
