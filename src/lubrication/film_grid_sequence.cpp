// Grid sequencing of the EHL film (film_grid_sequence.hpp).
#include "film_grid_sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>
#include <span>
#include <utility>

#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::lubrication {

namespace {

// The film on the grid of twice the spacing, interpolated onto op's grid as
// a Newton start, or nothing if there is no coarser grid, its film did not
// converge and `converged_only`, or its fields are not finite. Adds the
// coarse work to `record`, and a failed coarse film's message.
std::optional<ElasticFilm> sequenced_start(InfluenceOperator& op, const Eigen::ArrayXd& gap,
                                           const FlowConditions& conditions, const LubricantLaws& laws,
                                           const ElasticFilmOptions& options, bool converged_only,
                                           ElasticFilm& record) {
  const std::optional<ElasticFilm> coarse = detail::solve_on_coarser_grid(
      op, gap, options,
      [&](InfluenceOperator& coarse_op, const Eigen::ArrayXd& coarse_gap, const ElasticFilmOptions& coarse_options) {
        return solve_elastic_film(coarse_op, coarse_gap, conditions, laws, coarse_options);
      },
      record);
  if (!coarse) return std::nullopt;
  ElasticFilm film = *coarse;
  const Grid& grid = op.grid();
  const auto coarse_size = solvers::coarser_grid(grid, detail::kSequencingMinCells)->size();
  const auto coarse_n = static_cast<Eigen::Index>(coarse_size);
  const linalg::Communicator& comm = op.communicator();
  if (!detail::make_coarse_fields_whole(comm, *solvers::coarser_grid(grid, detail::kSequencingMinCells), film,
                                        {&film.pressure, &film.fluid_fraction})) {
    return std::nullopt;  // no fields to start from (on every process alike)
  }
  if (converged_only && !film.converged()) return std::nullopt;
  if (film.pressure.size() != coarse_n || !film.pressure.allFinite() || film.fluid_fraction.size() != coarse_n ||
      !film.fluid_fraction.allFinite()) {
    return std::nullopt;
  }
  // This process's rows of the fine start.
  const std::size_t own = op.local_size();
  const std::size_t first_row = linalg::first_row_held(comm, own / grid.nx());
  ElasticFilm start;
  start.pressure.resize(static_cast<Eigen::Index>(own));
  start.fluid_fraction.resize(start.pressure.size());
  solvers::prolong_bilinear_rows(grid, {film.pressure.data(), coarse_size}, first_row, {start.pressure.data(), own});
  solvers::prolong_bilinear_rows(grid, {film.fluid_fraction.data(), coarse_size}, first_row,
                                 {start.fluid_fraction.data(), own});
  // The coarse film's h0 carries over: the coarse gap is the fine one's
  // block average and the coarse K the fine one's.
  start.offset = film.offset;
  start.max_pressure = comm.max(own > 0 ? start.pressure.maxCoeff() : 0.0);
  return start;
}

}  // namespace

std::string detail::odd_grid_note(const Grid& grid) {
  const bool line = grid.dimension() == 1;
  if (grid.nx() % 2 == 0 && (line || grid.ny() % 2 == 0)) return {};
  return fmt::format(
      " (the {} grid has an odd node count, which grid sequencing cannot coarsen, so the film started cold: an even "
      "grid such as {} starts it from the coarser grids' film)",
      grid.shape_string(),
      line ? fmt::format("{}", grid.nx() + grid.nx() % 2)
           : fmt::format("{}x{}", grid.nx() + grid.nx() % 2, grid.ny() + grid.ny() % 2));
}

bool detail::make_coarse_fields_whole(const linalg::Communicator& comm, const Grid& coarse, NewtonFilmResult& film,
                                      std::initializer_list<Eigen::ArrayXd*> fields) {
  if (comm.size() <= 1) return true;
  const std::size_t coarse_size = coarse.size();
  const auto coarse_n = static_cast<Eigen::Index>(coarse_size);
  const auto whole_here = [&](const Eigen::ArrayXd& field) { return field.size() == coarse_n ? 1.0 : 0.0; };
  const auto rows_total = [&](const Eigen::ArrayXd& field) {
    std::array<double, 1> size{static_cast<double>(field.size())};
    comm.sum(size);
    return size[0];
  };
  double every_whole = 1.0;
  for (const Eigen::ArrayXd* field : fields) every_whole = std::min(every_whole, whole_here(*field));
  if (comm.min(every_whole) > 0.5) {
    // Solved whole on every process: the first process's film, so that they
    // start alike whatever their rounding.
    std::array<double, 2> scalars{film.offset, film.converged() ? 1.0 : 0.0};
    linalg::broadcast_from_first(comm, scalars);
    film.offset = scalars[0];
    film.status = scalars[1] > 0.5 ? FilmStatus::converged : FilmStatus::failure;
    for (Eigen::ArrayXd* field : fields) linalg::broadcast_from_first(comm, {field->data(), coarse_size});
    return true;
  }
  for (const Eigen::ArrayXd* field : fields) {
    if (rows_total(*field) != static_cast<double>(coarse_size)) return false;
  }
  // Solved on slabs of the coarse rows: the rows concatenated.
  const std::size_t unit = coarse.nx() * sizeof(double);
  for (Eigen::ArrayXd* field : fields) {
    Eigen::ArrayXd whole(coarse_n);
    comm.concatenate(std::as_bytes(std::span<const double>(field->data(), static_cast<std::size_t>(field->size()))),
                     std::as_writable_bytes(std::span<double>(whole.data(), coarse_size)), unit);
    *field = std::move(whole);
  }
  return true;
}

ElasticFilm solve_elastic_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                               const LubricantLaws& laws, const ElasticFilmOptions& options, const ElasticFilm* start) {
  const auto started = std::chrono::steady_clock::now();
  const Grid& grid = op.grid();
  conditions.validate(grid);
  laws.validate(conditions.viscosity);
  options.validate();
  // On several processes each holds its rows of `gap` (agreed: the
  // decision is collective).
  const bool sequence =
      options.grid_sequencing && start == nullptr && options.linear_solve != FilmLinearSolve::dense &&
      grid.size() > kAutomaticKrylovNodes &&
      op.communicator().min(static_cast<std::size_t>(gap.size()) == op.local_size() && gap.allFinite() ? 1.0 : 0.0) >
          0.5;
  if (!sequence) return detail::solve_film_newton(op, gap, conditions, laws, options, start);
  // The fine grid's memory first: the coarse grids would take minutes on a
  // grid the fine solve cannot hold.
  detail::agree_on_input(op.communicator(), [&] { detail::require_film_memory(grid, options, op.local_size()); });
  ElasticFilm record;
  // Up to kMaxColdRestartNodes a failed coarse film is dropped for the cold
  // start; above, the cold start cannot be expected to converge, and a
  // coarse film short of its tolerance is still the best start there is.
  const bool cold_allowed = grid.size() <= kMaxColdRestartNodes;
  const std::optional<ElasticFilm> coarse_start =
      sequenced_start(op, gap, conditions, laws, options, cold_allowed, record);
  ElasticFilm result =
      detail::solve_film_newton(op, gap, conditions, laws, options, coarse_start ? &*coarse_start : nullptr);
  if (coarse_start && !result.converged() && cold_allowed) {
    // A start that failed: the cold start's dry contact and start films.
    const int sequenced_steps = result.iterations;
    const int sequenced_krylov = result.krylov_iterations;
    result = detail::solve_film_newton(op, gap, conditions, laws, options, nullptr);
    result.iterations += sequenced_steps;
    result.krylov_iterations += sequenced_krylov;
    result.sequencing_fell_back = true;
  } else if (!coarse_start && !result.converged()) {
    // Not sequenced for the grid's odd shape alone: say how to be.
    result.message += detail::odd_grid_note(grid);
  } else if (coarse_start && !result.converged()) {
    result.message +=
        fmt::format(" (started from the coarser grids' film{}{}; no cold restart above {} nodes)",
                    record.message.empty() ? "" : ", which did not converge: ", record.message, kMaxColdRestartNodes);
  }
  result.coarse_levels = record.coarse_levels;
  result.coarse_iterations = record.coarse_iterations;
  result.coarse_krylov_iterations = record.coarse_krylov_iterations;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace halfspace::lubrication
