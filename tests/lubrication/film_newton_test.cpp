// The films' shared Newton driver (src/lubrication/film_newton.hpp) on a
// model whose every full step multiplies the residual's norm by a fixed
// rate: the stagnation rule (give up where the norm has not fallen below a
// share of its value some steps before) must end an iteration that creeps
// and leave one that converges, however slowly its rule allows, alone (and,
// where asked, hand over to the next start without ending the last); and
// on a model with a kink the watchdog must step over it where that pays and
// go back to the stall where it does not; a start's rule
// (FilmTolerances::start_norm_share) must end an iteration where the norm
// has fallen and the residuals are within the allowance, and only there;
// the step to the first kink must end a creep towards a kink.
#include "lubrication/film_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

namespace halfspace::lubrication::detail {
namespace {

constexpr double kTolerance = 1e-8;

// A scalar model's measure: the residual is its state.
FilmMeasure at(double value) {
  return {.norm = std::abs(value), .mass = std::abs(value), .load = 0.0, .contact = 0.0};
}

// What the models share: one start, a linear solve that always succeeds,
// the whole step in the trust region, at most 1000 steps, the state `x`.
FilmNewton model_newton(const double& x) {
  FilmNewton n;
  n.rules = {
      .words = {.solver = "the model's", .film = "the model", .krylov_step = "the model's "},
      .tolerances = {.mass = kTolerance, .load = kTolerance, .contact = std::nullopt, .start_norm_share = std::nullopt},
      .limit = 1000};
  n.measure = [&x] { return at(x); };
  n.lay_start = [](std::size_t) { return false; };
  n.solve = [](const FilmMeasure&, double, bool) {
    FilmNewtonSolve solved;
    solved.solved = true;
    return solved;
  };
  n.trust_region = [] { return 1.0; };
  return n;
}

struct CreepingModel {
  double rate = 0.5;  // the norm after a full step over the norm before
  double x = 1.0, trial = 1.0;
  int steps_taken = 0;

  FilmNewton newton(int stagnation_steps, double stagnation_share) {
    FilmNewton n = model_newton(x);
    n.rules.stagnation_steps = stagnation_steps;
    n.rules.stagnation_share = stagnation_share;
    n.try_step = [this](double scale, bool) -> std::optional<FilmMeasure> {
      trial = x * (1.0 - scale * (1.0 - rate));
      return at(trial);
    };
    n.accept = [this] {
      x = trial;
      ++steps_taken;
    };
    return n;
  }
};

TEST(FilmNewtonTest, StagnationRuleEndsACreepingIteration) {
  // 0.95 per step: 0.857 over three steps, above the share 0.75.
  CreepingModel creeping{.rate = 0.95};
  NewtonFilmResult result;
  run_film_newton(creeping.newton(3, 0.75), result);
  EXPECT_FALSE(result.converged());
  EXPECT_EQ(result.iterations, 3);
  EXPECT_NE(result.message.find("stagnated"), std::string::npos) << result.message;
  // Without the rule the same iteration converges (in log(1e-8) / log(0.95)
  // = 360 steps).
  CreepingModel unruled{.rate = 0.95};
  NewtonFilmResult converged;
  run_film_newton(unruled.newton(0, 1.0), converged);
  EXPECT_TRUE(converged.converged()) << converged.message;
  EXPECT_EQ(converged.iterations, static_cast<int>(std::ceil(std::log(kTolerance) / std::log(0.95))));
}

TEST(FilmNewtonTest, StagnationRuleLeavesAConvergingIterationAlone) {
  // 0.9 per step: 0.729 over three steps, below the share 0.75.
  CreepingModel slow{.rate = 0.9};
  NewtonFilmResult result;
  run_film_newton(slow.newton(3, 0.75), result);
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_EQ(result.iterations, static_cast<int>(std::ceil(std::log(kTolerance) / std::log(0.9))));
}

TEST(FilmNewtonTest, StagnationRuleCanHandOverWithoutEndingTheLastStart) {
  // Two starts, the rule for starts the next takes over from only (the EHL
  // film's): the first creeps at 0.999 per step and hands over after the
  // rule's 5 steps; the second converges at 0.1 per step.
  CreepingModel model{.rate = 0.999};
  FilmNewton two = model.newton(5, 0.99);
  two.rules.starts = 2;
  two.rules.share = 500;
  two.rules.stagnation_ends_last_start = false;
  two.lay_start = [&model](std::size_t) {
    model.x = 1.0;
    model.rate = 0.1;
    return true;
  };
  NewtonFilmResult result;
  run_film_newton(two, result);
  EXPECT_TRUE(result.converged()) << result.message;
  int fast_steps = 0;
  for (double y = 1.0; std::abs(y) > kTolerance; ++fast_steps) y *= 1.0 - (1.0 - 0.1);
  EXPECT_EQ(result.iterations, 5 + fast_steps);
  // On its last start the same rule leaves the creep of the first test
  // alone: it converges.
  CreepingModel last{.rate = 0.95};
  FilmNewton one = last.newton(3, 0.75);
  one.rules.stagnation_ends_last_start = false;
  NewtonFilmResult alone;
  run_film_newton(one, alone);
  EXPECT_TRUE(alone.converged()) << alone.message;
  EXPECT_EQ(alone.iterations, static_cast<int>(std::ceil(std::log(kTolerance) / std::log(0.95))));
}

// A model with a kink: from the start every step along the Newton
// direction, however short, raises the residual's norm by the step's
// length (a branch switch the linear model does not see); once across,
// every full step multiplies it by `rate`.
struct KinkedModel {
  double rate = 0.1;
  double x = 1.0, trial = 1.0, saved = 1.0;
  bool across = false, trial_across = false, saved_across = false;

  FilmNewton newton(int watchdog_steps) {
    FilmNewton n = model_newton(x);
    n.rules.watchdog_steps = watchdog_steps;
    n.try_step = [this](double scale, bool) -> std::optional<FilmMeasure> {
      trial = across ? x * (1.0 - scale * (1.0 - rate)) : x * (1.0 + scale);
      trial_across = true;
      return at(trial);
    };
    n.accept = [this] {
      x = trial;
      across = trial_across;
    };
    n.save = [this] {
      saved = x;
      saved_across = across;
    };
    n.restore = [this] {
      x = saved;
      across = saved_across;
    };
    return n;
  }
};

// The steps from norm `from` to the tolerance at `rate` per step.
int steps_to_tolerance(double from, double rate) {
  int steps = 0;
  for (double norm = from; norm > kTolerance; norm *= rate) ++steps;
  return steps;
}

TEST(FilmNewtonTest, WatchdogStepsOverAKink) {
  // Without the watchdog the line search finds no lower point: a stall.
  KinkedModel plain;
  NewtonFilmResult stalled;
  run_film_newton(plain.newton(0), stalled);
  EXPECT_FALSE(stalled.converged());
  EXPECT_NE(stalled.message.find("stalled at step 1"), std::string::npos) << stalled.message;
  EXPECT_EQ(stalled.watchdog_steps, 0);
  // With it the step across (norm 2) is taken, the next falls below the
  // stalled norm 1, and the iteration converges.
  KinkedModel watched;
  NewtonFilmResult result;
  run_film_newton(watched.newton(4), result);
  EXPECT_TRUE(result.converged()) << result.message;
  EXPECT_EQ(result.watchdog_steps, 1);
  EXPECT_EQ(result.iterations, 1 + steps_to_tolerance(2.0, 0.1));
  EXPECT_LE(std::abs(watched.x), kTolerance);
}

TEST(FilmNewtonTest, WatchdogGoesBackToTheStallWhereItDoesNotPay) {
  // Across the kink at 0.9 per step the norm needs 7 steps to fall from 2
  // below the stalled 1: more than the watchdog's 4, so the iteration
  // returns to the stalled point and reports the stall there.
  KinkedModel slow{.rate = 0.9};
  NewtonFilmResult result;
  run_film_newton(slow.newton(4), result);
  EXPECT_FALSE(result.converged());
  EXPECT_NE(result.message.find("stalled at step 1"), std::string::npos) << result.message;
  EXPECT_EQ(result.watchdog_steps, 1);
  EXPECT_EQ(result.iterations, 5);  // the step across and 4 more, all spent
  EXPECT_EQ(slow.x, 1.0);
  EXPECT_FALSE(slow.across);
  // Given 7 steps it pays.
  KinkedModel patient{.rate = 0.9};
  NewtonFilmResult converged;
  run_film_newton(patient.newton(7), converged);
  EXPECT_TRUE(converged.converged()) << converged.message;
  EXPECT_EQ(converged.iterations, 1 + steps_to_tolerance(2.0, 0.9));
}

// A node a hair above a kink (the cavitation switch at s = 0): the Newton
// direction, solved on the node's side, carries s to -c, and the residual's
// norm is s + c on that side. A trial past the kink holds the node at s = 0
// (the bent path) while the rest of the step goes on, which the norm pays
// for at 1e3 times the overshoot. On the kink the next solve takes the
// other branch, and every full step multiplies the norm by `rate`.
struct ZenoModel {
  double rate = 0.1, c = 1.0;
  double s = 1e-3, norm_on_kink = 0.0;  // s > 0: on its side; s == 0: on the kink
  double trial_s = 0.0, trial_norm = 0.0;

  double norm() const { return s > 0.0 ? s + c : norm_on_kink; }
  double kink_scale() const { return s / (s + c); }

  FilmNewton newton(bool with_first_kink) {
    FilmNewton n = model_newton(s);
    n.measure = [this] { return at(norm()); };
    n.try_step = [this](double scale, bool) -> std::optional<FilmMeasure> {
      if (s == 0.0) {
        trial_s = 0.0;
        trial_norm = norm_on_kink * (1.0 - scale * (1.0 - rate));
      } else if (scale <= kink_scale()) {
        trial_s = s - scale * (s + c);
        trial_norm = trial_s + c;
      } else {
        trial_s = 0.0;
        trial_norm = c + 1e3 * (scale - kink_scale()) * (s + c);
      }
      return at(trial_norm);
    };
    n.accept = [this] {
      if (s > 0.0 && trial_s == 0.0) norm_on_kink = trial_norm;
      if (s == 0.0) norm_on_kink = trial_norm;
      s = trial_s;
    };
    if (with_first_kink) {
      n.first_kink = [this](double longest) {
        const double at_kink = kink_scale() * (1.0 + 1e-12);
        return s > 0.0 && at_kink < longest ? at_kink : INFINITY;
      };
    }
    return n;
  }
};

// Halving alone creeps towards the kink: each accepted step stops short of
// it, s falls but never reaches 0, and the norm stays near c until no
// halving is short enough. With the step to the first kink (FilmNewton::
// first_kink) the node lands on it, the next solve takes the other branch,
// and the iteration converges at `rate` per step.
TEST(FilmNewtonTest, TheStepToTheFirstKinkEndsAZenoCreep) {
  ZenoModel halving;
  NewtonFilmResult crept;
  run_film_newton(halving.newton(false), crept);
  EXPECT_FALSE(crept.converged());
  EXPECT_GT(halving.s, 0.0);
  EXPECT_GT(halving.norm(), 0.99 * halving.c);
  EXPECT_NE(crept.message.find("no step along the Newton direction lowers the residual"), std::string::npos)
      << crept.message;

  ZenoModel kinked;
  NewtonFilmResult converged;
  run_film_newton(kinked.newton(true), converged);
  ASSERT_TRUE(converged.converged()) << converged.message;
  EXPECT_EQ(kinked.s, 0.0);
  EXPECT_EQ(converged.iterations, 1 + steps_to_tolerance(kinked.c, kinked.rate));
}

TEST(FilmNewtonTest, NoTightRetryWhileTheWatchdogRuns) {
  // A dead end: every step, on either side, raises the norm. GMRES steps:
  // at the stall the refused loose step is solved again to the tight
  // tolerance; from the watchdog's point a refused step ends the watchdog
  // at once, without a tight solve.
  double x = 1.0, trial = 1.0, saved = 1.0;
  int tight_solves = 0;
  FilmNewton n = model_newton(x);
  n.rules.krylov = true;
  n.rules.krylov_tolerance = 1e-12;
  n.rules.watchdog_steps = 4;
  n.solve = [&tight_solves](const FilmMeasure&, double, bool tight) {
    if (tight) ++tight_solves;
    FilmNewtonSolve solved;
    solved.solved = true;
    return solved;
  };
  n.try_step = [&](double scale, bool) -> std::optional<FilmMeasure> {
    trial = x * (1.0 + scale);
    return at(trial);
  };
  n.accept = [&] { x = trial; };
  n.save = [&] { saved = x; };
  n.restore = [&] { x = saved; };
  NewtonFilmResult result;
  const int tight_retries = run_film_newton(n, result);
  EXPECT_FALSE(result.converged());
  EXPECT_NE(result.message.find("stalled at step 1"), std::string::npos) << result.message;
  EXPECT_EQ(result.watchdog_steps, 1);
  EXPECT_EQ(tight_retries, 1);
  EXPECT_EQ(tight_solves, 1);
  EXPECT_EQ(x, 1.0);  // back at the stall
}

// A model whose residual's norm falls 20-fold per full step while its
// largest relative mass residual falls by a tenth (as the 1024^2 mixed
// film's did between speeds): the progress k after k full steps, the norm
// 0.05^k, the mass residual mass0 0.9^k.
struct UnevenModel {
  double mass0 = 0.02;
  double k = 0.0, trial = 0.0;

  FilmMeasure measured(double progress) const {
    const double norm = std::pow(0.05, progress);
    return {.norm = norm, .mass = mass0 * std::pow(0.9, progress), .load = 0.0, .contact = 0.0};
  }
  FilmNewton newton(std::optional<double> start_norm_share) {
    FilmNewton n = model_newton(k);
    n.rules.tolerances.mass = 3e-3;
    n.rules.tolerances.start_norm_share = start_norm_share;
    n.measure = [this] { return measured(k); };
    n.try_step = [this](double scale, bool) -> std::optional<FilmMeasure> {
      trial = k + scale;
      return measured(trial);
    };
    n.accept = [this] { k = trial; };
    return n;
  }
};

// A start's rule: a tenth of the first norm, with the mass residual within
// the check's allowance, ends the iteration after one step; without it the
// mass residual takes ceil(log(0.15) / log(0.9)) = 19.
TEST(FilmNewtonTest, AStartEndsWhereTheNormHasFallenTenfold) {
  UnevenModel start;
  NewtonFilmResult taken;
  run_film_newton(start.newton(0.1), taken);
  EXPECT_TRUE(taken.converged()) << taken.message;
  EXPECT_EQ(taken.iterations, 1);
  UnevenModel answer;
  NewtonFilmResult solved;
  run_film_newton(answer.newton(std::nullopt), solved);
  EXPECT_TRUE(solved.converged()) << solved.message;
  EXPECT_EQ(solved.iterations, 19);
}

// The norm's fall alone is not enough: with a mass residual ten times the
// start's above (0.2 0.9^k), the iteration goes on until the mass residual
// is within the allowance (3e-2: ceil(log(0.15) / log(0.9)) = 19 steps).
TEST(FilmNewtonTest, AStartStillNeedsItsResidualsWithinTheAllowance) {
  UnevenModel far{.mass0 = 0.2};
  NewtonFilmResult taken;
  run_film_newton(far.newton(0.1), taken);
  EXPECT_TRUE(taken.converged()) << taken.message;
  EXPECT_EQ(taken.iterations, 19);
  EXPECT_GT(far.measured(far.k).mass, 3e-3);
  EXPECT_LE(far.measured(far.k).mass, kCheckAllowance * 3e-3);
}

}  // namespace
}  // namespace halfspace::lubrication::detail
