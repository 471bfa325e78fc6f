// Progress line. The fraction of a step that is done is estimated from the
// residual on a log scale, log(r0 / r) / log(r0 / tol): the Polonsky-Keer
// residual falls roughly geometrically, so this is close to linear in the
// iterations. The remaining time extrapolates the elapsed time over the
// finished steps plus that fraction.
#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace halfspace::app {
namespace {

// Below this overall fraction an estimate of the remaining time is noise.
constexpr double kMinFractionForEstimate = 0.02;

}  // namespace

std::string format_duration(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return "?";
  if (seconds < 60.0) return fmt::format("{:.1f} s", seconds);
  const auto whole = static_cast<long long>(seconds + 0.5);
  if (whole < 3600) return fmt::format("{}m{:02}s", whole / 60, whole % 60);
  return fmt::format("{}h{:02}m", whole / 3600, (whole % 3600) / 60);
}

Progress::Progress(bool enabled, std::size_t steps, double tolerance)
    : active_(enabled && ::isatty(STDERR_FILENO) == 1), steps_(std::max<std::size_t>(steps, 1)), tolerance_(tolerance) {
  // For tests of the display: HALFSPACE_PROGRESS_INTERVAL=0 draws every iteration.
  if (const char* interval = std::getenv("HALFSPACE_PROGRESS_INTERVAL")) {
    char* end = nullptr;
    const double value = std::strtod(interval, &end);
    if (end != interval && value >= 0.0) interval_ = value;
  }
}

Progress::~Progress() {
  clear();
}

void Progress::start_step(std::size_t step, std::string load) {
  step_ = step;
  load_ = std::move(load);
  first_residual_ = 0.0;
}

void Progress::iteration(int iteration, double residual) {
  if (!active_) return;
  if (first_residual_ == 0.0 && residual > 0.0 && std::isfinite(residual)) first_residual_ = residual;
  const Clock::time_point now = Clock::now();
  const double since_start = std::chrono::duration<double>(now - start_).count();
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (since_start < interval_ || (drawn_ && since_draw < interval_)) return;
  last_draw_ = now;
  draw(iteration, residual);
}

void Progress::draw(int iteration, double residual) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  double step_fraction = 0.0;
  if (first_residual_ > tolerance_ && residual > 0.0 && std::isfinite(residual)) {
    step_fraction = std::log(first_residual_ / residual) / std::log(first_residual_ / tolerance_);
  }
  step_fraction = std::clamp(step_fraction, 0.0, 0.99);
  const double fraction = (static_cast<double>(step_) + step_fraction) / static_cast<double>(steps_);
  const std::string remaining = fraction >= kMinFractionForEstimate
                                    ? fmt::format("~{}", format_duration(elapsed * (1.0 - fraction) / fraction))
                                    : std::string("?");

  std::string line;
  if (steps_ > 1) line += fmt::format("step {}/{} ({})  ", step_ + 1, steps_, load_);
  line += fmt::format("iteration {}  residual {:.2e}  elapsed {}  remaining {}", iteration, residual,
                      format_duration(elapsed), remaining);
  // \r returns to the start of the line, ESC[K erases what a longer previous
  // line left behind.
  std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\x1b[K");
  std::fflush(stderr);
  drawn_ = false;
}

solvers::ProgressCallback Progress::callback() {
  if (!active_) return {};
  return [this](int iteration, double residual) {
    this->iteration(iteration, residual);
    return solvers::IterationDecision::proceed;
  };
}

}  // namespace halfspace::app
