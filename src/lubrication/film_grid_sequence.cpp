// The coarse operator and the interpolation of grid sequencing
// (film_grid_sequence.hpp).
#include "film_grid_sequence.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <optional>

#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::lubrication::detail {

CoarsenedInfluenceOperator::CoarsenedInfluenceOperator(InfluenceOperator& fine, const Grid& coarse)
    : fine_(fine), coarse_(coarse), fine_pressure_(fine.grid().size()), fine_displacement_(fine.grid().size()) {
  // A unit pressure on one coarse cell: its own displacement is K_ii.
  std::vector<double> unit(coarse_.size(), 0.0), column(coarse_.size(), 0.0);
  unit[0] = 1.0;
  apply(unit, column);
  self_influence_ = column[0];
}

void CoarsenedInfluenceOperator::apply(std::span<const double> pressure, std::span<double> displacement) {
  const Grid& fine_grid = fine_.grid();
  solvers::prolong_constant(fine_grid, pressure, fine_pressure_);
  fine_.apply(fine_pressure_, fine_displacement_);
  solvers::restrict_by_average(fine_grid, fine_displacement_, displacement);
}

namespace {

// The two coarse indices and the weight of the second for a fine index
// `i` on an axis of `coarse_count` coarse nodes.
struct Bracket {
  std::size_t low = 0, high = 0;
  double weight = 0.0;
};

Bracket bracket(std::size_t i, std::size_t coarse_count, bool periodic) {
  const double t = 0.5 * static_cast<double>(i) - 0.25;
  if (coarse_count == 1) return {};
  if (periodic) {
    const double low = std::floor(t);
    const auto n = static_cast<long>(coarse_count);
    const long l = ((static_cast<long>(low) % n) + n) % n;
    return {static_cast<std::size_t>(l), static_cast<std::size_t>((l + 1) % n), t - low};
  }
  const double clamped = std::clamp(t, 0.0, static_cast<double>(coarse_count - 1));
  const auto low = std::min(static_cast<std::size_t>(clamped), coarse_count - 2);
  return {low, low + 1, clamped - static_cast<double>(low)};
}

}  // namespace

void interpolate_to_fine(const Grid& fine, std::span<const double> coarse_values, std::span<double> fine_values) {
  const bool line = fine.dimension() == 1;
  const std::size_t nx = fine.nx(), ny = line ? 1 : fine.ny();
  const std::size_t cx = nx / 2, cy = line ? 1 : ny / 2;
  assert(fine_values.size() == nx * ny && coarse_values.size() == cx * cy);
  const bool periodic = fine.periodic();
  for (std::size_t j = 0; j < ny; ++j) {
    const Bracket y = line ? Bracket{} : bracket(j, cy, periodic);
    for (std::size_t i = 0; i < nx; ++i) {
      const Bracket x = bracket(i, cx, periodic);
      const auto at = [&](std::size_t row, std::size_t column) { return coarse_values[row * cx + column]; };
      const double low = (1.0 - x.weight) * at(y.low, x.low) + x.weight * at(y.low, x.high);
      const double high = (1.0 - x.weight) * at(y.high, x.low) + x.weight * at(y.high, x.high);
      fine_values[j * nx + i] = (1.0 - y.weight) * low + y.weight * high;
    }
  }
}

}  // namespace halfspace::lubrication::detail

namespace halfspace::lubrication {

namespace {

// Cells per axis below which no coarser grid is made.
constexpr std::size_t kSequencingMinCells = 8;

// The film on the grid of twice the spacing, interpolated onto op's grid as
// a Newton start, or nothing if there is no coarser grid or its film did not
// converge. Adds the coarse work to `record`.
std::optional<ElasticFilm> sequenced_start(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                           const FlowConditions& conditions, const LubricantLaws& laws,
                                           const ElasticFilmOptions& options, ElasticFilm& record) {
  const Grid& grid = op.grid();
  const std::optional<Grid> coarse = solvers::coarser_grid(grid, kSequencingMinCells);
  if (!coarse) return std::nullopt;
  detail::CoarsenedInfluenceOperator coarse_op(op, *coarse);
  Eigen::ArrayXd coarse_gap(static_cast<Eigen::Index>(coarse->size()));
  solvers::restrict_by_average(grid, {gap.data(), grid.size()}, {coarse_gap.data(), coarse->size()});
  ElasticFilmOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, kSequencingCoarseTolerance);
  coarse_options.load_tolerance = std::max(options.load_tolerance, kSequencingCoarseTolerance);
  const ElasticFilm film = solve_elastic_film(coarse_op, coarse_gap, conditions, laws, coarse_options);
  record.coarse_levels = 1 + film.coarse_levels;
  record.coarse_iterations = film.iterations + film.coarse_iterations;
  record.coarse_krylov_iterations = film.krylov_iterations + film.coarse_krylov_iterations;
  if (!film.converged()) return std::nullopt;
  ElasticFilm start;
  start.pressure.resize(static_cast<Eigen::Index>(grid.size()));
  start.fluid_fraction.resize(start.pressure.size());
  detail::interpolate_to_fine(grid, {film.pressure.data(), coarse->size()}, {start.pressure.data(), grid.size()});
  detail::interpolate_to_fine(grid, {film.fluid_fraction.data(), coarse->size()},
                              {start.fluid_fraction.data(), grid.size()});
  // The coarse film's h0 carries over: the coarse gap is the fine one's
  // block average and the coarse K the fine one's.
  start.offset = film.offset;
  start.max_pressure = start.pressure.maxCoeff();
  return start;
}

}  // namespace

ElasticFilm solve_elastic_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                               const LubricantLaws& laws, const ElasticFilmOptions& options, const ElasticFilm* start) {
  const auto started = std::chrono::steady_clock::now();
  const Grid& grid = op.grid();
  conditions.validate(grid);
  laws.validate(conditions.viscosity);
  options.validate();
  const bool sequence = options.grid_sequencing && start == nullptr && options.linear_solve != FilmLinearSolve::dense &&
                        grid.size() > kAutomaticKrylovNodes && op.local_size() == grid.size() &&
                        static_cast<std::size_t>(gap.size()) == grid.size() && gap.allFinite();
  if (!sequence) return detail::solve_film_newton(op, gap, conditions, laws, options, start);
  ElasticFilm record;
  const std::optional<ElasticFilm> coarse_start = sequenced_start(op, gap, conditions, laws, options, record);
  ElasticFilm result =
      detail::solve_film_newton(op, gap, conditions, laws, options, coarse_start ? &*coarse_start : nullptr);
  if (coarse_start && !result.converged()) {
    // A start that failed: the cold start's dry contact and start films.
    const int sequenced_steps = result.iterations;
    const int sequenced_krylov = result.krylov_iterations;
    result = detail::solve_film_newton(op, gap, conditions, laws, options, nullptr);
    result.iterations += sequenced_steps;
    result.krylov_iterations += sequenced_krylov;
    result.sequencing_fell_back = true;
  }
  result.coarse_levels = record.coarse_levels;
  result.coarse_iterations = record.coarse_iterations;
  result.coarse_krylov_iterations = record.coarse_krylov_iterations;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace halfspace::lubrication
