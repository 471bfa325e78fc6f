// The Newton driver the EHL film (elastic_film.cpp) and the mixed film
// (mixed_film.cpp) share: starts tried in turn, an inexact Newton step per
// iteration (Dembo, Eisenstat & Steihaug 1982) solved again tightly when no
// step along the loose direction lowers the residual, a trust region and a
// backtracking (Armijo) line search on the scaled residual's norm, and the
// divergence, stall and step-limit messages. Each film brings its physics
// as callbacks (its state, residual, linear solve and step) and names its
// own differences in FilmNewton. Private to the library.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "halfspace/lubrication/elastic_film.hpp"

namespace halfspace::lubrication::detail {

// A film's state measured: the scaled residual's norm (the line search's
// merit) and the relative residuals the converged test reads.
struct FilmMeasure {
  double norm = 0.0, mass = 0.0, load = 0.0, contact = 0.0;
};

// The converged test: the relative mass residual and the load error, and
// the contact rows' residual where the film has contact rows.
struct FilmTolerances {
  double mass = 0.0, load = 0.0;
  std::optional<double> contact;
  // A film that is only the next solve's start: converged also where the
  // residual's norm is at most this share of its value where the start's
  // iteration began and the relative residuals are within the check's
  // allowance (kCheckAllowance times the tolerances).
  std::optional<double> start_norm_share;
};

// How far past its tolerances the check after the iteration
// (check_after_newton) lets a converged film's measured residuals be.
inline constexpr double kCheckAllowance = 10.0;

// How loose a GMRES step may be (newton_forcing.hpp): the Newton
// residual's norm, or Eisenstat & Walker's choice from its history.
enum class FilmForcing { residual_norm, eisenstat_walker };

// The words of a film's messages: "<solver> Newton iteration diverged",
// "<film> did not converge in", "<krylov_step>Newton step 3: <GMRES's>".
struct FilmNewtonWords {
  std::string_view solver, film, krylov_step;
};

// What a Newton step's linear solve reports (its step is the film's).
struct FilmNewtonSolve {
  bool solved = false;
  int krylov_iterations = 0;   // all branch passes
  std::string krylov_message;  // GMRES's, where it failed
};

// A film's own rules of the iteration (its differences from the other's).
struct FilmNewtonRules {
  FilmNewtonWords words;
  FilmTolerances tolerances;
  FilmForcing forcing = FilmForcing::residual_norm;
  bool krylov = false;                // GMRES steps (else the dense LU's)
  double krylov_tolerance = 0.0;      // the tight solve's
  bool counts_refused_steps = false;  // a step the solve or line search refuses counts as a step
  std::size_t starts = 1;
  int share = 0;  // steps a start but the last gets before the next takes over (0: no hand-over)
  int limit = 0;  // steps in all
  // Whether the limit ends any start (else the last only: the others end
  // at their share, and the last may then have less than none left).
  bool limit_on_each_start = true;
  // Give up (a failure) where the residual's norm after a step is above
  // stagnation_share times its value stagnation_steps steps before (0: never).
  int stagnation_steps = 0;
  double stagnation_share = 1.0;
  // Whether the stagnation rule ends the last start too (else only a start
  // the next one takes over from).
  bool stagnation_ends_last_start = true;
  // The watchdog (Chamberlain, Powell, Lemarechal & Pedersen 1982): where
  // no step along the Newton direction lowers the residual, the trust
  // region's step is taken anyway, and the iteration goes back to the
  // stalled point (FilmNewton::save, restore) and reports the stall there
  // unless the residual's norm falls below the stalled one within this many
  // further steps (0: no watchdog; a film with one gives save and restore).
  int watchdog_steps = 0;
};

// The rules and the film's physics.
struct FilmNewton {
  FilmNewtonRules rules;
  // The current state's measure; the start `attempt` (> 0) laid into the
  // current state (false: it cannot be, the iteration ends).
  std::function<FilmMeasure()> measure;
  std::function<bool(std::size_t)> lay_start;
  // The Newton step at the current state to the relative residual `forcing`
  // (0: the tight solve to krylov_tolerance, `tight`), at the measure `current`.
  std::function<FilmNewtonSolve(const FilmMeasure& current, double forcing, bool tight)> solve;
  // The trust region's step length; where given, whether the step clipped
  // entry by entry to the trust region is tried first at that length.
  std::function<double()> trust_region;
  std::function<bool(double)> clip;
  // The trial state at `scale` times the step (or the clipped step) and its
  // measure; nothing where its film is not valid. `accept` takes the trial.
  std::function<std::optional<FilmMeasure>(double scale, bool clipped)> try_step;
  // Where given: the smallest scale below `longest` at which the step
  // carries a node just past a kink of the residual (the cavitation
  // switch), infinity if none. The line search tries it before halving
  // below it: halving alone crept towards a kink a node sat a hair above,
  // each step accepted at a few times less than the kink's scale and the
  // node never reaching it (a Zeno creep; docs/development-log.md,
  // 2026-12-04, forty-third session).
  std::function<double(double longest)> first_kink;
  std::function<void()> accept;
  // The watchdog's: keep the current state, and make it current again.
  std::function<void()> save, restore;
};

// Runs the Newton iteration from the current state, into `result`'s status,
// message, iterations, line search halvings and GMRES counts. Returns the
// tight retries (steps solved again to krylov_tolerance).
int run_film_newton(const FilmNewton& newton, NewtonFilmResult& result);

// The check apart from the iteration, after it converged: `result`'s
// relative mass residual and load error, measured after it stopped (and
// the contact complementarity `contact` where the film has contact rows),
// within kCheckAllowance times the tolerances, and the cavitation's
// complementarity (`complementary`). Else a failure.
void check_after_newton(const FilmNewtonRules& rules, double contact, bool complementary, NewtonFilmResult& result);

}  // namespace halfspace::lubrication::detail
