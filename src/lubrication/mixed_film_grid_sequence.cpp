// Grid sequencing of the mixed film (nested iteration, Venner & Lubrecht
// 2000, ch. 3), as the EHL film's (film_grid_sequence.cpp): the coarse
// grid's film (its influence operator R K P seen through the fine one, its
// gap the fine gap's block average) interpolated bilinearly, fluid and
// contact pressure and fluid fraction apart, with its h0, as the fine
// Newton start. The speed continuation a cold start needs in the mixed
// regime is then paid on the coarsest grid only. A coarse film is only a
// start (SolveEffort::start): it gets its own coarser start and, on the
// coarsest grid, the speed continuation, then one cold try with checked
// step branches, but none of the answer's other fall-backs (faster films,
// the cold restart, the retry with checked branches and continuations).
// Where it fails, the fine grid goes the faster films' way at once. On a
// measured map the coarse grids are the harder problem (at 3e-4 m/s 0.96
// of the load in contact at 32^2 against 0.16 at 256^2), and their
// fall-backs took most of the time (docs/development-log.md, 2026-12-01,
// twenty-seventh session). The exception: a 256^2 grid under a 512^2
// answer is an answer itself (kCoarseAnswerNodes).
#include "mixed_film_grid_sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <span>

#include "film_grid_sequence.hpp"
#include "halfspace/solvers/grid_transfer.hpp"
#include "mixed_film_keep.hpp"

namespace halfspace::lubrication {

namespace {

// The faster films tried where the fine iteration fails from the coarse one.
constexpr double kSequencedSpeedUp = 4.0;
constexpr double kSequencedFastest = 64.0;
// The Newton steps the fine grid gets from the coarse film before the
// faster film is tried (a rough point contact at 64^2: 55 steps; with 25,
// every level gave up and the solve took 200 steps; docs/development-log.md);
// fewer where the iteration stagnates on grids of at most kTryingNodes
// nodes (MixedStartUse::try_only). Up to 128^2 the tries from the coarse
// film failed on every rough point contact traced, after thousands of GMRES
// iterations; from 256^2 they converged, and giving up on stagnation there
// sent a 512^2 film the longer way round (docs/development-log.md,
// 2026-12-01). Above, a try ends where a step's GMRES stops short of its
// forcing term (MixedStartUse::try_until_short): the synthetic 256^2 and
// 512^2 films are unchanged, and a measured 256^2 window's try that failed
// after 14,576 GMRES iterations ends at its first step (1926 -> 1467 CPU
// s; docs/development-log.md, 2026-12-01, twenty-sixth session).
constexpr int kSequencedFirstSteps = 60;
constexpr std::size_t kTryingNodes = 128 * 128;
// A coarse grid of 256^2 nodes (up to, not including, 512^2) under an
// answer is solved as an answer itself (with the faster films and the speed
// continuation on it), not as a start: the continuation is then paid on
// the coarser grid, and the fine grid's try starts from its film at the
// speed asked. On the measured window resampled to 512^2 (1e-3 m/s) the
// 512^2 try from the 256^2 film took 8 Newton steps (48 s) where the 512^2
// continuation from 16 times the speed took 198 s. Below, the try costs more
// than the continuation (a 256^2 try from the 128^2 film: 34 steps, 6,285
// GMRES iterations, 98 s); above, the 1024^2 try from the 512^2 film failed
// after 20 minutes (docs/development-log.md, 2026-12-03, thirty-fifth
// session).
constexpr std::size_t kCoarseAnswerNodes = 256 * 256;
constexpr std::size_t kCoarseAnswerBelow = 512 * 512;

// What a grid's solve is for, and so which fall-backs it gets where its
// Newton iteration fails from its start:
//  - answer: the faster films and the speed continuation from them, and on
//    grids of at most kMaxMixedColdRestartNodes the cold restart;
//  - start: a film another solve starts from (a faster film the answer
//    continues from, a coarse grid's film the next grid starts from):
//    none, but the coarsest grid's speed continuation
//    (solve_mixed_film_on_grid), and for a coarse grid's film a cold try
//    with checked step branches where that fails (solve_start);
//  - quick_start: that try: coarser grids as quick_start, the coarsest
//    grid's Newton iteration from its cold starts alone.
enum class SolveEffort { answer, start, quick_start };

MixedFilm solve_sequenced(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                          const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                          const MixedFilm* start, SolveEffort effort, bool* coarser_grid_failed = nullptr);

// Adds the work of the failed solve `earlier` to the counts of `again`, the
// solve after it.
void add_earlier_work(MixedFilm& again, const MixedFilm& earlier) {
  again.iterations += earlier.iterations;
  again.krylov_iterations += earlier.krylov_iterations;
  again.line_search_halvings += earlier.line_search_halvings;
  again.max_krylov_iterations_per_step =
      std::max(again.max_krylov_iterations_per_step, earlier.max_krylov_iterations_per_step);
  again.coarse_iterations += earlier.coarse_iterations;
  again.coarse_krylov_iterations += earlier.coarse_krylov_iterations;
}

// A coarse grid's film as a start (SolveEffort::start or quick_start), with
// the checked try where a start fails; the work of both is counted. Not
// where the grid failed for want of a coarser film: its checked try would
// start from the coarser grid's checked try, which has just failed, and
// fail the same way (on the measured window at 1024^2 each grid from 128^2
// up repeated the 32^2 and 64^2 grids' checked solves, to the bit).
MixedFilm solve_start(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                      const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                      SolveEffort effort) {
  bool coarser_grid_failed = false;
  MixedFilm film = solve_sequenced(op, gap, keep, conditions, laws, options, nullptr, effort, &coarser_grid_failed);
  if (film.converged() || effort == SolveEffort::quick_start || options.checked_step_branches || coarser_grid_failed) {
    return film;
  }
  MixedFilmOptions checked = options;
  checked.checked_step_branches = true;
  MixedFilm again = solve_sequenced(op, gap, keep, conditions, laws, checked, nullptr, SolveEffort::quick_start);
  add_earlier_work(again, film);
  if (!again.converged())
    again.message = fmt::format("{} (a cold try with checked step branches: {})", film.message, again.message);
  return again;
}

// The film on the grid of twice the spacing, interpolated onto op's grid, or
// nothing if there is no coarser grid or its film did not converge. Adds the
// coarse work to `record`, and a failed coarse film's message. Sets
// `coarse_in_full_film` where the coarse film carries no contact load.
std::optional<MixedFilm> sequenced_start(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                                         const FlowConditions& conditions, const LubricantLaws& laws,
                                         const MixedFilmOptions& options, SolveEffort effort, MixedFilm& record,
                                         bool& coarse_in_full_film) {
  const std::optional<MixedFilm> coarse = detail::solve_on_coarser_grid(
      op, gap, options,
      [&](InfluenceOperator& coarse_op, const Eigen::ArrayXd& coarse_gap, const MixedFilmOptions& coarse_options) {
        const std::size_t coarse_nodes = coarse_op.grid().size();
        if (effort == SolveEffort::answer && coarse_nodes >= kCoarseAnswerNodes && coarse_nodes < kCoarseAnswerBelow) {
          return solve_sequenced(coarse_op, coarse_gap, keep, conditions, laws, coarse_options, nullptr,
                                 SolveEffort::answer);
        }
        return solve_start(coarse_op, coarse_gap, keep, conditions, laws, coarse_options,
                           effort == SolveEffort::quick_start ? SolveEffort::quick_start : SolveEffort::start);
      },
      record);
  if (!coarse) return std::nullopt;
  MixedFilm film = *coarse;
  coarse_in_full_film = film.contact_load_fraction == 0.0;
  const Grid& grid = op.grid();
  const Grid coarse_grid = *solvers::coarser_grid(grid, detail::kSequencingMinCells);
  const std::size_t coarse_size = coarse_grid.size();
  // On several processes the coarse film whole on every process
  // (film_grid_sequence.hpp), this process's rows of the fine start.
  const linalg::Communicator& comm = op.communicator();
  if (!detail::make_coarse_fields_whole(comm, coarse_grid, film, {&film.fluid_pressure, &film.fluid_fraction}) ||
      !film.converged()) {
    return std::nullopt;
  }
  const std::size_t n = op.local_size();
  const std::size_t first_row = linalg::first_row_held(comm, n / grid.nx());
  MixedFilm start;
  const auto prolong = [&](const Eigen::ArrayXd& coarse_values, Eigen::ArrayXd& fine_values) {
    fine_values.resize(static_cast<Eigen::Index>(n));
    solvers::prolong_bilinear_rows(grid, {coarse_values.data(), coarse_size}, first_row, {fine_values.data(), n});
  };
  prolong(film.fluid_pressure, start.fluid_pressure);
  prolong(film.fluid_fraction, start.fluid_fraction);
  // The contact pressure is not interpolated: the fine roughness puts the
  // contacts elsewhere than its block average does, and an interpolated one
  // closes cells that are open on the fine grid (at 64^2: 184 contact rows
  // closed, 46 at the solution, and no Newton step descends from there). It
  // is the fine dry contact's under the interpolated fluid pressure instead,
  // carrying what the fluid does not: the contact rows then hold and the
  // load balances at the start, the Newton iteration corrects the fluid.
  double fluid_sum = start.fluid_pressure.sum();
  if (comm.size() > 1) comm.sum(std::span(&fluid_sum, 1));
  const double fluid_load = fluid_sum * grid.cell_area();
  Eigen::ArrayXd loaded_gap(static_cast<Eigen::Index>(n));
  op.apply({start.fluid_pressure.data(), n}, {loaded_gap.data(), n});
  loaded_gap += gap;
  start.contact_pressure = Eigen::ArrayXd::Zero(static_cast<Eigen::Index>(n));
  // The coarse h0 where no contact remains: the coarse gap is the fine one's
  // block average and the coarse K the fine one's.
  start.offset = film.offset;
  if (options.load - fluid_load > 0.0) {
    const solvers::SolveResult contact =
        detail::solve_dry_contact(op, loaded_gap, solvers::Loading::force(options.load - fluid_load));
    if (contact.converged()) {
      start.contact_pressure = contact.pressure;
      start.offset = -contact.approach;
    }
  }
  start.entrainment_speed = film.entrainment_speed;
  start.status = FilmStatus::converged;
  return start;
}

// solve_mixed_film without its checked retry, with the fall-backs `effort`
// allows. Sets `coarser_grid_failed` (if given) where the grid is sequenced
// and its coarser grid gave no film.
MixedFilm solve_sequenced(InfluenceOperator& op, const Eigen::ArrayXd& gap, detail::MixedFilmKeep& keep,
                          const FlowConditions& conditions, const LubricantLaws& laws, const MixedFilmOptions& options,
                          const MixedFilm* start, SolveEffort effort, bool* coarser_grid_failed) {
  const auto started = std::chrono::steady_clock::now();
  const Grid& grid = op.grid();
  options.validate();
  // On several processes each holds its rows of `gap` (agreed: the
  // decision is collective). A grid of odd shape has no coarser grid: it is
  // the coarsest, solved from its cold starts with the speed continuation
  // (as the first grid of at most kMixedSequencingNodes is).
  const bool wanted = options.grid_sequencing && start == nullptr && options.load_controlled() &&
                      grid.dimension() == 2 && options.linear_solve != FilmLinearSolve::dense &&
                      grid.size() > kMixedSequencingNodes;
  const bool coarsens = solvers::coarser_grid(grid, detail::kSequencingMinCells).has_value();
  const bool sequence =
      wanted && coarsens &&
      op.communicator().min(static_cast<std::size_t>(gap.size()) == op.local_size() && gap.allFinite() ? 1.0 : 0.0) >
          0.5;
  if (!sequence) {
    MixedFilm film = detail::solve_mixed_film_on_grid(op, gap, keep, conditions, laws, options, start,
                                                      effort == SolveEffort::quick_start
                                                          ? detail::MixedStartUse::solve_only
                                                          : detail::MixedStartUse::solve_then_continue);
    if (wanted && !film.converged() && effort == SolveEffort::answer) film.message += detail::odd_grid_note(grid);
    return film;
  }
  // The fine grid's memory first: the coarse grids would take minutes on a
  // grid the fine solve cannot hold.
  detail::agree_on_input(op.communicator(),
                         [&] { require_mixed_film_fits(grid, options, "the mixed film", op.local_size()); });
  MixedFilm record;
  bool coarse_in_full_film = false;
  const std::optional<MixedFilm> coarse_start =
      sequenced_start(op, gap, keep, conditions, laws, options, effort, record, coarse_in_full_film);
  if (coarser_grid_failed != nullptr) *coarser_grid_failed = !coarse_start;
  MixedFilm result;
  if (coarse_start) {
    // A start in full film (its coarser film carries no contact load) is
    // solved only to the start tolerance, as the speed continuation's films
    // between are: the 1024^2 film at 0.016 m/s that the measured window's
    // continuation starts from took 12 Newton steps to 1e-8, 7 to the start
    // tolerance, and the answer was the same to every printed digit
    // (docs/development-log.md, 2026-12-04, forty-seventh session).
    // Above kTryingNodes it also stops where a step has lowered the
    // residual's norm to kStartNormShare of its first value, as those films
    // between do: at 1024^2 that film then took 5 Newton steps (294 GMRES
    // iterations) instead of 7 (454), the 512^2 one under it 3 (182) instead
    // of 5 (420) (docs/development-log.md, 2026-12-04, forty-eighth
    // session).
    const bool only_a_start = effort == SolveEffort::start && coarse_in_full_film;
    MixedFilmOptions first = only_a_start ? detail::full_film_start_options(options) : options;
    first.max_iterations = std::min(options.max_iterations, kSequencedFirstSteps);
    const detail::MixedStartUse use = grid.size() <= kTryingNodes ? detail::MixedStartUse::try_only
                                      : only_a_start              ? detail::MixedStartUse::try_as_start
                                                                  : detail::MixedStartUse::try_until_short;
    result = detail::solve_mixed_film_on_grid(op, gap, keep, conditions, laws, first, &*coarse_start, use);
  }
  int steps = result.iterations, krylov = result.krylov_iterations;
  // A fine Newton iteration that failed from the coarse film (its steps
  // creep where cells cross the contact and the film floor h_b at once):
  // the film at a faster speed, grid-sequenced in turn (4, 16, ... times the
  // velocities: the faster, the further from contact and the easier), and
  // the continuation in the speed from it on this grid.
  const bool answer = effort == SolveEffort::answer;
  for (double faster = kSequencedSpeedUp; answer && !result.converged() && faster <= kSequencedFastest;
       faster *= kSequencedSpeedUp) {
    const MixedFilm fast = solve_sequenced(op, gap, keep, detail::at_speed_factor(conditions, faster), laws, options,
                                           nullptr, SolveEffort::start);
    steps += fast.iterations;
    krylov += fast.krylov_iterations;
    record.coarse_iterations += fast.coarse_iterations;
    record.coarse_krylov_iterations += fast.coarse_krylov_iterations;
    if (!fast.converged()) continue;
    result = detail::solve_mixed_film_on_grid(op, gap, keep, conditions, laws, options, &fast,
                                              detail::MixedStartUse::continue_only);
    steps += result.iterations;
    krylov += result.krylov_iterations;
    result.sequencing_fell_back = true;
    break;
  }
  if (!result.converged() && answer && grid.size() <= kMaxMixedColdRestartNodes) {
    // The last resort on small grids: the cold start with its continuations.
    result = detail::solve_mixed_film_on_grid(op, gap, keep, conditions, laws, options, nullptr);
    steps += result.iterations;
    krylov += result.krylov_iterations;
    result.sequencing_fell_back = true;
  } else if (!result.converged()) {
    result.message =
        fmt::format("{} (grid-sequenced; no cold restart above {} nodes){}", result.message, kMaxMixedColdRestartNodes,
                    record.message.empty() ? "" : fmt::format("; the coarser grids: {}", record.message));
  }
  result.iterations = steps;
  result.krylov_iterations = krylov;
  result.coarse_levels = record.coarse_levels;
  result.coarse_iterations = record.coarse_iterations;
  result.coarse_krylov_iterations = record.coarse_krylov_iterations;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace

MixedFilm detail::solve_mixed_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, MixedFilmKeep& keep,
                                   const FlowConditions& conditions, const LubricantLaws& laws,
                                   const MixedFilmOptions& options, const MixedFilm* start) {
  const auto started = std::chrono::steady_clock::now();
  MixedFilm film = solve_sequenced(op, gap, keep, conditions, laws, options, start, SolveEffort::answer);
  // A point contact that failed with the look-ahead's steps as they come:
  // again with checked steps (MixedFilmOptions::checked_step_branches), its
  // coarser grids too. Both solves' work is counted.
  if (film.converged() || options.checked_step_branches || op.grid().dimension() != 2) return film;
  MixedFilmOptions checked = options;
  checked.checked_step_branches = true;
  MixedFilm again = solve_sequenced(op, gap, keep, conditions, laws, checked, start, SolveEffort::answer);
  add_earlier_work(again, film);
  if (!again.converged()) {
    again.message =
        fmt::format("{} (also with checked step branches; with the look-ahead's: {})", again.message, film.message);
  }
  again.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return again;
}

MixedFilm solve_mixed_film(InfluenceOperator& op, const Eigen::ArrayXd& gap, const FlowConditions& conditions,
                           const LubricantLaws& laws, const MixedFilmOptions& options, const MixedFilm* start) {
  // Every grid's dry contact solved once for all its solves, one GMRES basis.
  detail::MixedFilmKeep keep;
  return detail::solve_mixed_film(op, gap, keep, conditions, laws, options, start);
}

}  // namespace halfspace::lubrication
