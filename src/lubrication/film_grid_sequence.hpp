// Grid sequencing for the EHL Newton iteration (nested iteration, Venner &
// Lubrecht 2000, ch. 3 "full multigrid"): the film solved on the grid of
// twice the spacing is interpolated onto the fine grid as its Newton start,
// so that the fine Newton iteration only corrects the discretisation
// difference. Private to the library.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "film_krylov_solver.hpp"
#include "film_slab.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/lubrication/elastic_film.hpp"
#include "halfspace/operators/coarsened_influence_operator.hpp"
#include "halfspace/operators/influence_operator.hpp"
#include "halfspace/operators/spectral_transforms.hpp"
#include "halfspace/solvers/grid_transfer.hpp"

namespace halfspace::lubrication::detail {

// Cells per axis below which no coarser grid is made.
inline constexpr std::size_t kSequencingMinCells = 8;

// Where `grid` has an odd cell count (which no coarser grid halves): the
// note a failed film's message ends with, saying why it started cold and
// which even grid would be sequenced; empty otherwise. Shared by the EHL and
// the mixed film.
std::string odd_grid_note(const Grid& grid);

// Rows of a coarse grid that every process must get for the coarse film to
// be solved on slabs (else it is solved whole on every process).
inline constexpr std::size_t kMinSlabRows = 16;

// The film `solve(coarse_op, coarse_gap, coarse_options)` gives on the grid
// of twice op's spacing: its operator R K P seen through op, its gap the
// block average of `gap`, its tolerances at least kSequencingCoarseTolerance
// (on a distributed op, the coarse film on slabs of the coarse rows, or
// whole on every process where they would be too thin).
// Its work is added to `record` (and its message, if it failed). Nothing if
// op's grid has no coarser grid. Shared by the EHL and the mixed film.
template <class Film, class Options, class Solve>
std::optional<Film> solve_on_coarser_grid(InfluenceOperator& op, const Eigen::ArrayXd& gap, const Options& options,
                                          Solve&& solve, Film& record) {
  const Grid& grid = op.grid();
  const std::optional<Grid> coarse = solvers::coarser_grid(grid, kSequencingMinCells);
  if (!coarse) return std::nullopt;
  // On a distributed operator `gap` is this process's rows, and the coarse
  // film is solved on slabs of the coarse rows too, unless a process would
  // hold fewer than kMinSlabRows of them: then whole on every process.
  const linalg::Communicator& comm = op.communicator();
  std::unique_ptr<operators::SpectralTransforms> transforms = op.transforms_for(*coarse);
  if (comm.size() > 1 &&
      comm.min(static_cast<double>(transforms->local_size() / coarse->nx())) < static_cast<double>(kMinSlabRows)) {
    transforms = operators::make_serial_transforms(*coarse, FftPlanning::estimate, {.count = 1});
  }
  CoarsenedInfluenceOperator coarse_op(op, *coarse, std::move(transforms));
  Eigen::ArrayXd coarse_gap(static_cast<Eigen::Index>(coarse->size()));
  const auto own = static_cast<std::size_t>(gap.size());
  solvers::restrict_rows_by_average(grid, {gap.data(), own}, linalg::first_row_held(comm, own / grid.nx()),
                                    {coarse_gap.data(), coarse->size()}, comm);
  if (coarse_op.local_size() != coarse->size()) {
    const std::size_t first =
        linalg::first_row_held(coarse_op.communicator(), coarse_op.local_size() / coarse->nx()) * coarse->nx();
    coarse_gap =
        coarse_gap.segment(static_cast<Eigen::Index>(first), static_cast<Eigen::Index>(coarse_op.local_size())).eval();
  }
  Options coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, kSequencingCoarseTolerance);
  coarse_options.load_tolerance = std::max(options.load_tolerance, kSequencingCoarseTolerance);
  Film film = solve(coarse_op, coarse_gap, coarse_options);
  record.coarse_levels = 1 + film.coarse_levels;
  if (!film.converged()) record.message = film.message;
  record.coarse_iterations = film.iterations + film.coarse_iterations;
  record.coarse_krylov_iterations = film.krylov_iterations + film.coarse_krylov_iterations;
  return film;
}

// On several processes (`comm`), the fields of a film solved on the grid
// `coarse` made whole on every process: where each process solved it whole,
// the first process's fields, h0 and status taken by all (so that they
// start alike whatever their rounding); where it was solved on slabs of the
// coarse rows, the rows concatenated. False (on every process alike) when
// the fields are neither. Nothing to do on one process.
bool make_coarse_fields_whole(const linalg::Communicator& comm, const Grid& coarse, NewtonFilmResult& film,
                              std::initializer_list<Eigen::ArrayXd*> fields);

// The Newton iteration of solve_elastic_film on the operator's grid alone
// (no grid sequencing): from `start` if it holds a film of this grid, else
// from the dry contact (elastic_film.cpp).
ElasticFilm solve_film_newton(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                              const LubricantLaws& laws, const ElasticFilmOptions& options, const ElasticFilm* start);

// The GMRES settings of the options.
FilmKrylovSettings film_krylov_settings(const ElasticFilmOptions& options);

// Throws InputError naming the grid if the GMRES path's memory estimate
// (film_krylov_memory_estimate) for this process's `nodes` exceeds the
// memory available.
void require_film_memory(const Grid& grid, const ElasticFilmOptions& options, std::size_t nodes);

// The largest |mass balance| over this process's unknown nodes of `slab`
// (fields on its stencil, halo current), relative to the largest Couette
// outflow, reduced over the processes: elastic_film_residual's check.
double film_flux_residual(const FilmSlab& slab, const ReynoldsStencil& topology, const FlowConditions& conditions,
                          const LubricantLaws& laws, const Eigen::ArrayXd& film, const Eigen::ArrayXd& pressure,
                          const Eigen::ArrayXd& fluid_fraction, CouetteScheme scheme);

}  // namespace halfspace::lubrication::detail
