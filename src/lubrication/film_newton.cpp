#include "film_newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "newton_forcing.hpp"

namespace halfspace::lubrication::detail {

namespace {

// The clipped step's tries (1, 1/2, 1/4 of it) before the scaled step's.
constexpr int kClippedHalvings = 3;
// The scaled step's halvings before the line search gives up.
constexpr int kMostHalvings = 30;
// Armijo's sufficient decrease of the residual's norm (Dennis & Schnabel
// 1983, sec. 6.3).
constexpr double kSufficientDecrease = 1e-4;

// `first_norm`: the residual's norm where the start's iteration began.
bool converged(const FilmTolerances& tolerances, const FilmMeasure& measured, double first_norm) {
  const auto within = [&](double scale) {
    return measured.mass <= scale * tolerances.mass && measured.load <= scale * tolerances.load &&
           (!tolerances.contact || measured.contact <= scale * *tolerances.contact);
  };
  return within(1.0) || (tolerances.start_norm_share && measured.norm <= *tolerances.start_norm_share * first_norm &&
                         within(kCheckAllowance));
}

// The relative residuals for a message, with their tolerances or without.
std::string residuals(const FilmTolerances& tolerances, const FilmMeasure& measured, bool with_tolerances) {
  const auto one = [&](std::string_view name, double value, double tolerance) {
    return with_tolerances ? fmt::format("{} {:.3g} (tolerance {:.3g})", name, value, tolerance)
                           : fmt::format("{} {:.3g}", name, value);
  };
  std::string text = one("relative mass residual", measured.mass, tolerances.mass) + ", " +
                     one("load error", measured.load, tolerances.load);
  if (tolerances.contact) text += ", " + one("contact residual", measured.contact, *tolerances.contact);
  return text;
}

}  // namespace

int run_film_newton(const FilmNewton& newton, NewtonFilmResult& result) {
  const FilmNewtonRules& rules = newton.rules;
  const FilmTolerances& tolerances = rules.tolerances;
  const double smallest_tolerance = std::min({tolerances.mass, tolerances.load, tolerances.contact.value_or(1.0)});
  int steps = 0, tight_retries = 0;
  for (std::size_t attempt = 0;; ++attempt) {
    result.status = FilmStatus::failure;
    result.message.clear();
    const bool last = attempt + 1 >= rules.starts;
    const bool hands_over = !last && rules.share > 0;
    const bool limited = last || rules.limit_on_each_start;
    FilmMeasure current = newton.measure();
    // The forcing term's history (newton_forcing): this start's steps only.
    double previous_norm = 0.0, forcing = kLargestForcing;
    std::vector<double> norms{current.norm};  // after each of this start's steps (the stagnation rule's)
    // The watchdog's stalled point (its measure and message) while it runs.
    std::optional<FilmMeasure> stalled;
    std::string stall_message;
    int watched = 0;
    const auto back_to_stall = [&] {
      newton.restore();
      current = newton.measure();
      stalled.reset();
      result.message = stall_message;
    };
    for (int iteration = 0;; ++iteration) {
      if (converged(tolerances, current, norms.front())) {
        result.status = FilmStatus::converged;
        break;
      }
      if (!std::isfinite(current.norm)) {
        result.message = fmt::format("{} Newton iteration diverged after {} steps", rules.words.solver, steps);
        break;
      }
      // This start has used its share of the steps: the rest to the next.
      if (hands_over && iteration == rules.share) break;
      if (limited && steps == rules.limit) {
        if (stalled) back_to_stall();
        result.status = FilmStatus::iteration_limit;
        result.message = fmt::format("{} did not converge in {} Newton steps: {}", rules.words.film, steps,
                                     residuals(tolerances, current, true));
        break;
      }
      // An inexact Newton step: GMRES to the forcing term, solved again to
      // krylov_tolerance when no step along the loose direction lowers the
      // residual (near the solution the loose direction's error can outweigh
      // the descent it promises).
      forcing = rules.forcing == FilmForcing::eisenstat_walker
                    ? newton_forcing(current.norm, previous_norm, forcing, kLargestForcing, smallest_tolerance)
                    : std::min(kLargestForcing, current.norm);
      previous_norm = current.norm;
      bool accepted = false, failed = false;
      FilmMeasure tried;
      for (const bool tight : {false, true}) {
        // Not while the watchdog runs: its point is only a trial, and a
        // step refused there ends it. From one, the 1024^2 mixed film's
        // tight solves took 16 GMRES solves (300 s) and no step descended;
        // on the traced levels none of them led back below the stall
        // (docs/development-log.md, 2026-12-03, thirty-seventh session).
        if (tight && (!(rules.krylov && forcing > rules.krylov_tolerance) || stalled)) break;
        if (tight) ++tight_retries;
        const FilmNewtonSolve solve = newton.solve(current, tight ? 0.0 : forcing, tight);
        result.krylov_iterations += solve.krylov_iterations;
        result.max_krylov_iterations_per_step =
            std::max(result.max_krylov_iterations_per_step, solve.krylov_iterations);
        if (!solve.solved) {
          result.message = rules.krylov ? fmt::format("{}Newton step {}: {}", rules.words.krylov_step, steps + 1,
                                                      solve.krylov_message)
                                        : fmt::format("{} Newton step {} is singular", rules.words.solver, steps + 1);
          failed = true;
          break;
        }
        // The trust region's length, then backtracking on the scaled
        // residual's norm; where the film clips, first the clipped step and
        // its halves, judged as the scaled step.
        double lambda = newton.trust_region();
        // Whether `scale` times the step (or the clipped one) lowers the
        // norm by Armijo's share of `length`; nothing where its film is not
        // valid.
        const auto lowers = [&](double scale, bool clipped, double length) -> std::optional<bool> {
          const std::optional<FilmMeasure> measured = newton.try_step(scale, clipped);
          if (!measured) return std::nullopt;
          tried = *measured;
          return std::isfinite(tried.norm) && tried.norm <= (1.0 - kSufficientDecrease * length) * current.norm;
        };
        if (newton.clip && newton.clip(lambda)) {
          for (int halving = 0; halving < kClippedHalvings && !accepted; ++halving) {
            const double mu = std::ldexp(1.0, -halving);
            accepted = lowers(mu, true, mu * lambda).value_or(false);
          }
          if (accepted) break;
        }
        // Where the halving is about to pass below the step's first kink,
        // the step to that kink first (newton.first_kink).
        const double kink = newton.first_kink ? newton.first_kink(lambda) : INFINITY;
        for (int halving = 0; halving <= kMostHalvings && !accepted; ++halving, lambda *= 0.5) {
          const std::optional<bool> lower = lowers(lambda, false, lambda);
          accepted = lower.value_or(false);
          if (lower && !accepted) ++result.line_search_halvings;
          if (!accepted && kink > 0.5 * lambda && kink < lambda) accepted = lowers(kink, false, kink).value_or(false);
        }
        if (accepted) break;
      }
      // Past a stall, a step the solve or the line search refuses ends
      // the watchdog: back to the stalled point.
      if (!accepted && stalled) {
        if (rules.counts_refused_steps) ++steps;
        back_to_stall();
        break;
      }
      if (!accepted && !failed) {
        result.message = fmt::format(
            "{} Newton iteration stalled at step {}: no step along the Newton direction lowers the residual ({})",
            rules.words.solver, steps + 1, residuals(tolerances, current, false));
        // The watchdog: the trust region's step taken anyway, from a
        // saved point to come back to.
        if (rules.watchdog_steps > 0) {
          const std::optional<FilmMeasure> measured = newton.try_step(newton.trust_region(), false);
          if (measured && std::isfinite(measured->norm)) {
            newton.save();
            stalled = current;
            stall_message = std::move(result.message);
            result.message.clear();
            watched = 0;
            tried = *measured;
            accepted = true;
            ++result.watchdog_steps;
          }
        }
      }
      if (accepted || rules.counts_refused_steps) ++steps;
      if (!accepted) break;
      newton.accept();
      current = tried;
      norms.push_back(current.norm);
      if (stalled) {
        if (current.norm <= (1.0 - kSufficientDecrease) * stalled->norm) {
          stalled.reset();
        } else if (++watched > rules.watchdog_steps) {
          back_to_stall();
          break;
        }
      }
      const auto window = static_cast<std::size_t>(rules.stagnation_steps);
      if (window > 0 && (!last || rules.stagnation_ends_last_start) && norms.size() > window &&
          !converged(tolerances, current, norms.front()) &&
          current.norm > rules.stagnation_share * norms[norms.size() - 1 - window]) {
        result.message = fmt::format(
            "{} Newton iteration stagnated: the residual's norm fell from {:.3g} to {:.3g} in {} steps ({})",
            rules.words.solver, norms[norms.size() - 1 - window], current.norm, window,
            residuals(tolerances, current, false));
        break;
      }
    }
    if (result.status != FilmStatus::failure || last) break;
    if (!newton.lay_start(attempt + 1)) break;
  }
  result.iterations = steps;
  return tight_retries;
}

void check_after_newton(const FilmNewtonRules& rules, double contact, bool complementary, NewtonFilmResult& result) {
  const FilmTolerances& tolerances = rules.tolerances;
  if (!result.converged() ||
      (result.relative_residual <= kCheckAllowance * tolerances.mass &&
       result.load_error <= kCheckAllowance * tolerances.load &&
       (!tolerances.contact || contact <= kCheckAllowance * *tolerances.contact) && complementary)) {
    return;
  }
  result.status = FilmStatus::failure;
  result.message = fmt::format(
      "{} check failed after the Newton iteration stopped: relative mass residual {:.3g}, load error {:.3g}",
      rules.words.solver, result.relative_residual, result.load_error);
  if (tolerances.contact) result.message += fmt::format(", contact complementarity {:.3g}", contact);
}

}  // namespace halfspace::lubrication::detail
