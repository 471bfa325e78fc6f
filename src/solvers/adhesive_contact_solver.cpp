// The adhesive contact energy minimised by preconditioned conjugate
// gradients (the default) or spectral projected gradients, and the load
// control around them (adhesive_contact_solver.hpp). SPG costs one product
// with the stiffness S (one FFT pair) per iteration: the trial energies of
// its line search reuse S v and S d, since the elastic energy is quadratic
// along a line; the conjugate gradients two or three.
#include "halfspace/solvers/adhesive_contact_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/fft/even_symbol.hpp"
#include "halfspace/fft/real_fft.hpp"
#include "halfspace/kernels/love_rectangle.hpp"
#include "halfspace/kernels/periodic_fourier.hpp"
#include "halfspace/kernels/plane_strain_strip.hpp"
#include "halfspace/linalg/parallel.hpp"
#include "halfspace/material.hpp"
#include "halfspace/solvers/interface_law.hpp"
#include "halfspace/solvers/solver_options.hpp"

namespace halfspace::solvers {
namespace {

// Non-monotone line search of SPG (Grippo, Lampariello & Lucidi 1986): a
// step is accepted against the largest of the last kMemory energies, which
// lets the Barzilai-Borwein steps through the narrow valleys of an
// ill-conditioned energy.
constexpr std::size_t kMemory = 10;
constexpr double kSufficientDecrease = 1e-4;
constexpr int kMaxBacktracks = 40;
// S v is updated along the steps (S v += lambda S d); it is recomputed from v
// this often, so rounding does not accumulate.
constexpr int kRefreshEvery = 50;
// The cohesive zone (AdhesionLaw::cohesive_zone_length) against the cell
// length: below kUnresolvedZone of a cell the grid cannot represent the law
// at a contact edge (its answer would be the grid's, not the law's), and the
// law is refused; below kUnderresolvedZone a result with a contact edge
// carries a warning.
constexpr double kUnresolvedZone = 0.01;
constexpr double kUnderresolvedZone = 0.1;

std::size_t mirrored(std::size_t k, std::size_t n) {
  return k <= n ? k : 2 * n - k;
}

}  // namespace

void AdhesiveSolverOptions::validate() const {
  const auto text = [](auto value) { return fmt::format("{}", value); };
  if (!(std::isfinite(law.work) && law.work > 0.0)) {
    throw SolverOptionError("law.work", text(law.work), "is invalid: must be positive and finite (J/m^2)");
  }
  if (!(std::isfinite(law.range) && law.range > 0.0)) {
    throw SolverOptionError("law.range", text(law.range), "is invalid: must be positive and finite (m)");
  }
  if (!std::isnormal(law.stress()) || !std::isfinite(law.stress())) {
    throw SolverOptionError("law.range", text(law.range),
                            fmt::format("is invalid with law.work = {}: the stress work / range = {} Pa must be "
                                        "finite and normal",
                                        law.work, law.stress()));
  }
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw SolverOptionError("tolerance", text(tolerance), "is invalid: allowed range is (0, 1)");
  }
  if (!(force_tolerance > 0.0 && force_tolerance < 1.0)) {
    throw SolverOptionError("force_tolerance", text(force_tolerance), "is invalid: allowed range is (0, 1)");
  }
  if (max_iterations < 1) {
    throw SolverOptionError("max_iterations", text(max_iterations), "is invalid: must be at least 1");
  }
  if (max_load_steps < 1) {
    throw SolverOptionError("max_load_steps", text(max_load_steps), "is invalid: must be at least 1");
  }
  InterfaceLaw{hardness}.validate();
}

double cell_length(const Grid& grid) {
  return grid.dimension() == 1 ? grid.dx() : std::max(grid.dx(), grid.dy());
}

// The law on this body and grid: its cohesive zone resolved (see
// kUnresolvedZone) and its largest force over the domain finite.
void check_law_on_grid(const AdhesionLaw& law, double e_star, const Grid& grid) {
  const double zone = law.cohesive_zone_length(e_star);
  const double cell = cell_length(grid);
  if (!(zone >= kUnresolvedZone * cell)) {
    throw InputError(fmt::format(
        "adhesion-range = {:.6g} m (adhesion stress {:.6g} Pa, work-of-adhesion {:.6g} J/m^2) is invalid on this grid: "
        "its cohesive zone at a contact edge, pi E* w / (4 sigma0^2) = {:.3g} m at E* = {:.6g} Pa, is {:.3g} of the "
        "cell length {:.6g} m (at least {} needed), so the grid cannot represent the law; use a longer range (a "
        "smaller stress) or a finer grid",
        law.range, law.stress(), law.work, zone, e_star, zone / cell, cell, kUnresolvedZone));
  }
  // The sums of the solve: the law's stress over every cell (a pull on the
  // whole domain) and its work.
  const double cells = static_cast<double>(grid.size());
  if (!(std::isfinite(4.0 * law.stress() * cells * std::max(1.0, grid.cell_area())) &&
        std::isfinite(4.0 * law.work * cells * std::max(1.0, grid.cell_area())))) {
    throw InputError(fmt::format(
        "work-of-adhesion = {:.6g} J/m^2 with adhesion-range = {:.6g} m is invalid on this grid: the adhesive stress "
        "{:.6g} Pa over its {} cells overflows the total force",
        law.work, law.range, law.stress(), grid.size()));
  }
}

struct AdhesiveContactSolver::Impl {
  Impl(const Grid& g, double e, AdhesiveSolverOptions o)
      : grid((check_law_on_grid(o.law, checked_composite_modulus(e), g), g)),
        e_star(checked_composite_modulus(e)),
        options(std::move(o)),
        padded(!g.periodic()),
        capped(options.hardness.has_value()),
        hardness(options.hardness.value_or(std::numeric_limits<double>::infinity())),
        rows(g.dimension() == 1 ? 1 : (padded ? 2 * g.ny() : g.ny())),
        cols(padded ? 2 * g.nx() : g.nx()),
        fft(rows == 1 ? RealFft(cols, options.fft_planning) : RealFft(rows, cols, options.fft_planning)),
        kernel(rows, cols / 2 + 1),
        stiffness(rows, cols / 2 + 1) {
    const std::size_t m = rows * cols;
    for (Eigen::ArrayXd* a : {&x, &sx, &gradient, &trial, &direction, &s_direction, &offset, &lower}) a->resize(m);
    if (options.precondition) {
      scaled.resize(m);
      old_gradient.resize(m);
    }
    physical.assign(m, 0);
    below.assign(m, 0);
    for (std::size_t k = 0; k < grid.size(); ++k) physical[index(k)] = 1;
    if (padded) {
      init_free();
    } else {
      init_periodic();
    }
    // K_ii: the displacement of cell 0 under unit pressure on it alone.
    trial.setZero();
    trial[0] = 1.0;
    apply(kernel, trial, direction);
    compliance = direction[0];
  }

  // Index in the variable's array of grid cell k ((ny, nx) row-major).
  std::size_t index(std::size_t k) const { return padded ? (k / grid.nx()) * cols + k % grid.nx() : k; }
  std::size_t size() const { return rows * cols; }

  void init_periodic() {
    const double inverse_m = 1.0 / static_cast<double>(size());
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      const double qy = grid.dimension() == 1 ? 0.0 : kernels::dft_wavenumber(r, grid.ny(), grid.dy());
      for (std::size_t c = 0; c < kernel.cols(); ++c) {
        const double q = std::hypot(kernels::dft_wavenumber(c, grid.nx(), grid.dx()), qy);
        kernel.at(r, c) = kernels::periodic_kernel_spectrum(q, e_star) * inverse_m;
        // The mean mode has no stiffness: the mean displacement is held at
        // 0 by the projection instead.
        stiffness.at(r, c) = q > 0.0 ? 0.5 * e_star * q * inverse_m : 0.0;
      }
    }
  }

  // The circulant of the DC-FFT convolution on the padded grid (as the FFT
  // operator builds it) and its inverse.
  void init_free() {
    const std::size_t nx = grid.nx();
    const std::size_t ny = grid.ny();
    const bool line = grid.dimension() == 1;
    std::span<double> input = fft.input();
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t dj = line ? 0 : mirrored(r, ny);
      for (std::size_t c = 0; c < cols; ++c) {
        const double x_offset = static_cast<double>(mirrored(c, nx)) * grid.dx();
        input[r * cols + c] = line ? kernels::plane_strain_strip_displacement(x_offset, grid.dx(), e_star)
                                   : kernels::love_rectangle_displacement(x_offset, static_cast<double>(dj) * grid.dy(),
                                                                          0.5 * grid.dx(), 0.5 * grid.dy(), e_star);
      }
    }
    fft.forward();
    const std::span<const std::complex<double>> spectrum = fft.spectrum();
    const double inverse_m = 1.0 / static_cast<double>(size());
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < kernel.stored_rows(); ++r) {
      for (std::size_t c = 0; c < kernel.cols(); ++c) {
        const double k = spectrum[r * kernel.cols() + c].real();
        smallest = std::min(smallest, k);
        kernel.at(r, c) = k * inverse_m;
        stiffness.at(r, c) = k > 0.0 ? inverse_m / k : 0.0;
      }
    }
    if (!(smallest > 0.0)) {
      throw InputError(fmt::format(
          "adhesion on the free {} grid: the padded influence kernel is not positive definite (smallest eigenvalue "
          "{:g} m/Pa), so the stiffness the adhesive solver minimises with does not exist; use a periodic grid{}",
          grid.shape_string(), smallest, line ? " or a domain shorter than 1 m (the strip kernel's datum)" : ""));
    }
  }

  // out = symbol applied to in (the unnormalised FFT pair with 1/M folded in).
  void apply(const EvenSymbol& symbol, const Eigen::ArrayXd& in, Eigen::ArrayXd& out) {
    const std::size_t m = size();
    if (!fft.forward_from({in.data(), m})) {
      std::span<double> input = fft.input();
      linalg::for_each_index(m, [&](std::size_t i) { input[i] = in[static_cast<Eigen::Index>(i)]; });
      fft.forward();
    }
    symbol.multiply(fft.spectrum());
    if (!fft.backward_into({out.data(), m})) {
      fft.backward();
      std::span<const double> output = fft.output();
      linalg::for_each_index(m, [&](std::size_t i) { out[static_cast<Eigen::Index>(i)] = output[i]; });
    }
  }

  // The shift tau of the projection of y onto {v >= lower} and (periodic)
  // mean v = 0: P(y) = max(lower, y - tau), with tau the root of the
  // convex, decreasing, piecewise linear mean, found by Newton's method from
  // the left, exact once a step clips no new cell; 0 on free grids. y(i)
  // gives y's entries (an array, or an expression such as v - c G that is
  // never stored). Empty if no feasible point exists.
  template <class Y>
  std::optional<double> projection_shift(Y&& y) const {
    if (padded) return 0.0;
    if (capped) return capped_projection_shift(y);
    const std::size_t m = size();
    const auto sum_and_free = [&](double tau) {
      return linalg::sums<2>(m, [&](std::size_t i) {
        const double v = y(i) - tau;
        return v > lower[i] ? std::array<double, 2>{v, 1.0} : std::array<double, 2>{lower[i], 0.0};
      });
    };
    double tau = linalg::sum(m, [&](std::size_t i) { return y(i); }) / static_cast<double>(m);
    std::array<double, 2> s = sum_and_free(tau);
    for (int k = 0; k < 1000; ++k) {
      if (s[1] == 0.0) return std::nullopt;
      tau += s[0] / s[1];
      const std::array<double, 2> next = sum_and_free(tau);
      const bool exact = next[1] == s[1];
      s = next;
      if (exact) break;
    }
    return tau;
  }

  // With a hardness cap: y - tau moved onto cell i's side of the kink
  // (below: g <= 0, above: g >= 0); without, max(lower, y - tau).
  double onto_side(std::size_t i, double shifted) const {
    return below[i] ? std::min(lower[i], shifted) : std::max(lower[i], shifted);
  }

  // projection_shift with a cap: the sum of the projection onto the sides
  // is still decreasing, continuous and piecewise linear in tau, but neither
  // convex nor concave, so Newton's steps are kept inside a bracket of the
  // root and replaced by bisection where they leave it, until the sum is
  // zero to rounding (relative to the sum of |P(y)|).
  template <class Y>
  std::optional<double> capped_projection_shift(Y&& y) const {
    const std::size_t m = size();
    // The sum of P(y), its count of unclipped cells and the sum of |P(y)|.
    const auto sums_at = [&](double tau) {
      return linalg::sums<3>(m, [&](std::size_t i) {
        const double shifted = y(i) - tau;
        const double z = onto_side(i, shifted);
        return std::array<double, 3>{z, z == shifted ? 1.0 : 0.0, std::abs(z)};
      });
    };
    double tau = linalg::sum(m, [&](std::size_t i) { return y(i); }) / static_cast<double>(m);
    double low = -std::numeric_limits<double>::infinity();  // sum above 0
    double high = std::numeric_limits<double>::infinity();  // sum below 0
    std::array<double, 3> s = sums_at(tau);
    double scale = std::abs(tau);
    for (int k = 0; k < 400; ++k) {
      if (!std::isfinite(s[0])) return std::nullopt;
      if (std::abs(s[0]) <= 1e-14 * s[2]) return tau;
      (s[0] > 0.0 ? low : high) = tau;
      if (std::isfinite(low) && std::isfinite(high) && !(high - low > 1e-15 * (std::abs(low) + std::abs(high)))) {
        return tau;
      }
      double next = s[1] > 0.0 ? tau + s[0] / s[1] : std::numeric_limits<double>::quiet_NaN();
      if (!(next > low && next < high)) {
        if (std::isfinite(low) && std::isfinite(high)) {
          next = 0.5 * (low + high);
        } else {
          // No slope and no bracket yet: double the step outwards.
          scale = 2.0 * scale + s[2] / static_cast<double>(m);
          next = tau + (s[0] > 0.0 ? scale : -scale);
        }
      }
      tau = next;
      s = sums_at(tau);
    }
    return std::nullopt;
  }

  // z = the projection of y (see projection_shift); false if no feasible
  // point exists.
  bool project(const Eigen::ArrayXd& y, Eigen::ArrayXd& z) const {
    const std::optional<double> tau = projection_shift([&](std::size_t i) { return y[i]; });
    if (!tau) return false;
    if (capped) {
      linalg::for_each_index(size(), [&](std::size_t i) { z[i] = onto_side(i, y[i] - *tau); });
    } else {
      linalg::for_each_index(size(), [&](std::size_t i) { z[i] = std::max(lower[i], y[i] - *tau); });
    }
    return true;
  }

  // The stopping residual (see Stopping in the header): the largest entry of
  // P(v - c G) - v over c p_ref, without storing the step. p_ref is the
  // largest pressure of the state: |S v| anywhere and the law's traction on
  // the cells off the wall; not the law's stress, which may exceed every
  // pressure of the contact by orders of magnitude (a short range) and so
  // would call any start converged. Its floor, for states without pressure
  // (surfaces apart, v -> 0), is the smaller of the stress and the pressure
  // that moves a cell by the law's range (range / c): below it a step
  // changes no cell's gap by more than the tolerance times the range.
  double residual_of_step(double c) const {
    const auto y = [&](std::size_t i) { return x[i] - c * gradient[i]; };
    const double tau = projection_shift(y).value_or(std::numeric_limits<double>::quiet_NaN());
    const AdhesionLaw& law = options.law;
    // The two maxima and the count of non-finite entries (which std::max
    // would drop).
    using Maxima = std::array<double, 3>;
    const Maxima largest = linalg::reduce_in_blocks(
        size(), Maxima{0.0, 0.0, 0.0},
        [&](Maxima& acc, std::size_t i) {
          const double step = std::abs((capped ? onto_side(i, y(i) - tau) : std::max(lower[i], y(i) - tau)) - x[i]);
          acc[0] = std::max(acc[0], step);
          acc[2] += std::isfinite(step) ? 0.0 : 1.0;
          acc[1] = std::max(acc[1], std::abs(sx[i]));
          if (physical[i] && off_wall(i)) acc[1] = std::max(acc[1], std::abs(cell_traction(law, offset[i] + x[i])));
        },
        [](Maxima& total, const Maxima& part) {
          total[0] = std::max(total[0], part[0]);
          total[1] = std::max(total[1], part[1]);
          total[2] += part[2];
        });
    if (!std::isfinite(tau) || largest[2] > 0.0) return std::numeric_limits<double>::quiet_NaN();
    const double floor = std::min(options.law.stress(), options.law.range / c);
    return largest[0] / (c * std::max(largest[1], floor));
  }

  // The interaction energy sum_i phi(g_i + step * d_i) over the grid cells.
  double interaction_energy(const Eigen::ArrayXd& v, const Eigen::ArrayXd* d, double step) const {
    const AdhesionLaw& law = options.law;
    return linalg::sum(size(), [&](std::size_t i) {
      if (!physical[i]) return 0.0;
      const double g = offset[i] + v[i] + (d ? step * (*d)[i] : 0.0);
      return cell_energy(law, g);
    });
  }

  // The interaction energy per area at gap g, with the cap's plastic work
  // below the kink (see Hardness cap in the header).
  double cell_energy(const AdhesionLaw& law, double g) const {
    return capped && g < 0.0 ? law.energy(0.0) - hardness * g : law.energy(std::max(g, 0.0));
  }
  // The pressure the interface exerts at gap g: H below the kink (the
  // traction above it at g = 0, the side settle() may change).
  double cell_traction(const AdhesionLaw& law, double g) const {
    return capped && g < 0.0 ? hardness : law.traction(std::max(g, 0.0));
  }
  // Whether cell i is off the wall (the kink): its gradient vanishes there
  // at the solution, so it measures the periodic multiplier.
  bool off_wall(std::size_t i) const { return capped ? x[i] != lower[i] : x[i] > lower[i]; }

  // With a cap: the side of every cell for the next step, and the gradient
  // of the cells on the kink: released below (gradient S v - H) when their
  // pressure, less the periodic multiplier `shift`, exceeds H; otherwise
  // above (S v - t(0), held or released as without a cap).
  void settle(double shift) {
    if (!capped) return;
    const double jump = hardness - options.law.traction(0.0);
    linalg::for_each_index(size(), [&](std::size_t i) {
      if (x[i] == lower[i]) {
        const bool flows = gradient[i] - jump - shift > 0.0;
        if (flows) gradient[i] -= jump;
        below[i] = flows ? 1 : 0;
      } else {
        below[i] = x[i] < lower[i] ? 1 : 0;
      }
    });
  }

  // gradient = S v - t(g) on the grid, S v on the padding (with a cap,
  // the sides settled).
  void make_gradient() {
    const AdhesionLaw& law = options.law;
    linalg::for_each_index(size(), [&](std::size_t i) {
      gradient[i] = physical[i] ? sx[i] - cell_traction(law, offset[i] + x[i]) : sx[i];
    });
    if (capped) settle(mean_shift());
  }

  // Whether cell i is held by the wall: at its bound with the gradient,
  // less the multiplier `shift` of the periodic mean constraint, pushing
  // into the wall.
  // With a cap, only a cell on the kink above it (settle()).
  bool binding(std::size_t i, double shift) const {
    if (capped) return x[i] == lower[i] && !below[i] && gradient[i] - shift > 0.0;
    return x[i] <= lower[i] && gradient[i] - shift > 0.0;
  }

  // With a cap: a cell on the kink released to one side whose conjugate
  // direction points to the other (the compliance mixes the cells) would be
  // clipped back by every step, and stay on the kink with its pressure
  // beyond the bounds; its component is the diagonally scaled gradient
  // -c (G - shift) instead, which points to its side (the two-metric
  // projection's diagonal near a bound, Bertsekas 1982), and the direction
  // is made mean-free again on the free cells (periodic). Returns the slope
  // G.d.
  double keep_released_sides(double shift) {
    const std::size_t m = size();
    const double c = compliance;
    // sum of d and count over the free cells, G.d, sum of G over them
    const std::array<double, 4> parts = linalg::sums<4>(m, [&](std::size_t i) {
      if (binding(i, shift)) return std::array<double, 4>{};
      if (x[i] == lower[i] && (below[i] ? direction[i] > 0.0 : direction[i] < 0.0)) {
        direction[i] = -c * (gradient[i] - shift);
      }
      return std::array<double, 4>{direction[i], 1.0, gradient[i] * direction[i], gradient[i]};
    });
    return mean_free_on_free_cells(parts, shift);
  }

  // The direction made mean-free on the cells the wall does not hold
  // (periodic: mean v = 0 then holds along the line), from the sums over
  // those cells {sum d, count, G.d, sum G}; returns the slope G.d of the
  // result. Free grids have no mean constraint.
  double mean_free_on_free_cells(const std::array<double, 4>& parts, double shift) {
    if (padded || !(parts[1] > 0.0)) return parts[2];
    const double mu = parts[0] / parts[1];
    linalg::for_each_index(size(), [&](std::size_t i) {
      if (!binding(i, shift)) direction[i] -= mu;
    });
    return parts[2] - mu * parts[3];
  }

  // The periodic grid's multiplier of mean v = 0: the mean gradient over the
  // cells off the wall (0 on free grids, which have no such constraint).
  double mean_shift() const {
    if (padded) return 0.0;
    const std::array<double, 2> free_part = linalg::sums<2>(size(), [&](std::size_t i) {
      return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
    });
    return free_part[1] > 0.0 ? free_part[0] / free_part[1] : 0.0;
  }

  double dot(const Eigen::ArrayXd& a, const Eigen::ArrayXd& b) const {
    return linalg::sum(size(), [&](std::size_t i) { return a[i] * b[i]; });
  }

  // What the iterations carry from one step to the next: the energy and
  // the last kMemory energies (the non-monotone line searches), the
  // periodic multiplier, the restart flag and rho = (G - shift).D(G -
  // shift) of the conjugate gradients, and SPG's Barzilai-Borwein step.
  // Conjugate gradients restart after a step the wall clipped (or a plain
  // projected gradient step); a change of the held set alone does not
  // restart (Polak-Ribiere+ resets itself where the new gradient
  // contradicts the old direction, and restarting there cost 10-35 % more
  // iterations on the rough benchmark).
  struct Walk {
    SolveResult& result;
    double energy = 0.0;
    std::array<double, kMemory> recent{};
    double free_shift = 0.0;
    bool restart = true;
    double rho_old = 0.0;
    double alpha = 0.0;
  };
  // One iteration of either minimiser from the state in x, sx and gradient
  // at `residual`: true if it moved, false if it broke down (the result's
  // status and message then say why).
  bool conjugate_gradient_step(Walk& walk, int iteration, double residual);
  bool spectral_gradient_step(Walk& walk, int iteration, double residual);
  SolveResult solve_displacement(std::span<const double> initial_gap, double approach,
                                 std::span<const double> initial_pressure, bool start_from_last);
  SolveResult solve_force(std::span<const double> initial_gap, double target, std::span<const double> initial_pressure);
  void fill_result(SolveResult& result, std::span<const double> initial_gap, double approach);

  Grid grid;
  double e_star;
  AdhesiveSolverOptions options;
  bool padded;
  bool capped;      // a hardness cap is set
  double hardness;  // H (Pa), infinite without a cap
  std::size_t rows;
  std::size_t cols;
  RealFft fft;
  EvenSymbol kernel;     // K: the kernel spectrum over M
  EvenSymbol stiffness;  // S = K^-1 over M (0 at the periodic mean mode)
  double compliance = 0.0;
  std::vector<unsigned char> physical;  // 1 on the grid's cells, 0 on the padding
  std::vector<unsigned char> below;     // with a cap: 1 where the cell's side is below the kink (settle())
  // Workspace over the variable's array: v, S v, the gradient, the trial
  // point P(v - alpha G), the step d, S d, the offset h - delta (gap =
  // offset + v) and the bound delta - h (-inf on the padding).
  Eigen::ArrayXd x, sx, gradient, trial, direction, s_direction, offset, lower;
  Eigen::ArrayXd scaled, old_gradient;   // preconditioned solves only: D G (or S of a trial point), the last G
  Eigen::ArrayXd saved_low, saved_high;  // load control: the displacements of the bracket's ends
  bool have_last = false;                // x holds the last solve's displacement
  double last_approach = 0.0;
};

SolveResult AdhesiveContactSolver::Impl::solve_displacement(std::span<const double> initial_gap, double approach,
                                                            std::span<const double> initial_pressure,
                                                            bool start_from_last) {
  const auto started = std::chrono::steady_clock::now();
  const std::size_t m = size();
  const double inf = std::numeric_limits<double>::infinity();
  offset.setZero();
  lower.setConstant(-inf);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    offset[index(k)] = initial_gap[k] - approach;
    lower[index(k)] = approach - initial_gap[k];
  }
  if (!padded && !(lower.mean() < 0.0)) {
    throw InputError(fmt::format(
        "approach = {} m is invalid for a periodic surface: it must be below the mean initial gap {} m (full contact "
        "needs infinite pressure there)",
        approach, approach - lower.mean()));
  }
  // The start: the last solution's displacement, K p of the given pressure,
  // or 0, projected onto the constraints.
  if (!start_from_last) {
    direction.setZero();
    if (!initial_pressure.empty()) {
      for (std::size_t k = 0; k < grid.size(); ++k) direction[index(k)] = initial_pressure[k];
      apply(kernel, direction, direction);
    }
    x = direction;
  }
  SolveResult result;
  result.solver = options.precondition ? "adhesive-pcg" : "adhesive-spg";  // as name()
  result.tolerance = options.tolerance;
  // With a cap, every cell starts above the kink (the projection puts the
  // penetrating ones on it; those pressed beyond H are released below at
  // once), but for the last solve's plastic cells when continuing from it.
  if (capped) {
    linalg::for_each_index(m, [&](std::size_t i) { below[i] = start_from_last && x[i] < lower[i] ? 1 : 0; });
  }
  if (!project(x, x)) {
    result.status = SolveStatus::breakdown;
    result.message = "no displacement satisfies the constraints";
    return result;
  }
  apply(stiffness, x, sx);
  result.operator_applications = 1;
  make_gradient();
  Walk walk{result};
  walk.free_shift = mean_shift();
  walk.energy = 0.5 * dot(x, sx) + interaction_energy(x, nullptr, 0.0);
  walk.recent.fill(walk.energy);
  walk.alpha = compliance;
  const double c = compliance;
  result.status = SolveStatus::iteration_limit;
  for (int iteration = 0;; ++iteration) {
    // Residual: the projected gradient step of length c, in pressure.
    const double residual = residual_of_step(c);
    result.residual = residual;
    result.iterations = iteration;
    if (result.residual_history.size() < 100000) result.residual_history.push_back(residual);
    if (options.progress) options.progress(iteration, residual);
    if (!std::isfinite(residual)) {
      result.status = SolveStatus::breakdown;
      result.message = fmt::format("the residual is not finite at iteration {}", iteration);
      break;
    }
    if (residual <= options.tolerance) {
      result.status = SolveStatus::converged;
      break;
    }
    if (iteration >= options.max_iterations) {
      result.message = fmt::format("no convergence in {} iterations: residual {:.3g} > tolerance {:.3g}", iteration,
                                   residual, options.tolerance);
      break;
    }
    const bool stepped = options.precondition ? conjugate_gradient_step(walk, iteration, residual)
                                              : spectral_gradient_step(walk, iteration, residual);
    if (!stepped) break;
  }
  have_last = result.converged();
  last_approach = approach;
  fill_result(result, initial_gap, approach);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

bool AdhesiveContactSolver::Impl::conjugate_gradient_step(Walk& walk, int iteration, double residual) {
  SolveResult& result = walk.result;
  double& energy = walk.energy;
  std::array<double, kMemory>& recent = walk.recent;
  double& free_shift = walk.free_shift;
  bool& restart = walk.restart;
  double& rho_old = walk.rho_old;
  const std::size_t m = size();
  const double c = compliance;
  // Preconditioned non-linear conjugate gradients on the free cells
  // (Polak-Ribiere+), the wall's cells held, the step the minimiser of
  // the elastic energy along d, clipped onto the wall and backtracked
  // until the energy falls (Armijo, monotone). The vector work is fused
  // into few passes: at these sizes a pass over the fields costs a
  // fair fraction of an FFT pair.
  // scaled = D (G - shift) on the cells the wall does not hold, 0 on
  // those it holds: D is the compliance K's principal block on the free
  // cells. K inverts the elastic stiffness that makes the plain gradient
  // ill-conditioned (symbol E*|q|/2). One FFT pair.
  const double shift = free_shift;
  linalg::for_each_index(m, [&](std::size_t i) { scaled[i] = binding(i, shift) ? 0.0 : gradient[i] - shift; });
  apply(kernel, scaled, scaled);
  ++result.operator_applications;
  // D (G - shift) vanishes on the held cells; rho and the Polak-Ribiere
  // numerator in the same pass.
  const std::array<double, 2> sums = linalg::sums<2>(m, [&](std::size_t i) {
    if (binding(i, shift)) scaled[i] = 0.0;
    return std::array<double, 2>{scaled[i] * (gradient[i] - shift),
                                 restart ? 0.0 : scaled[i] * (gradient[i] - old_gradient[i])};
  });
  double beta = 0.0;
  if (!restart && rho_old > 0.0) beta = std::max(0.0, sums[1] / rho_old);
  rho_old = sums[0];
  // d = -D G + b d on the free cells, mean-free on them (periodic: mean
  // v = 0 holds along the line); returns the slope G.d.
  const auto make_direction = [&](double b) {
    // sum of d and count over the free cells, G.d, sum of G over the free cells
    const std::array<double, 4> parts = linalg::sums<4>(m, [&](std::size_t i) {
      if (binding(i, shift)) {
        direction[i] = 0.0;
        return std::array<double, 4>{0.0, 0.0, 0.0, 0.0};
      }
      direction[i] = -scaled[i] + b * direction[i];
      return std::array<double, 4>{direction[i], 1.0, gradient[i] * direction[i], gradient[i]};
    });
    return mean_free_on_free_cells(parts, shift);
  };
  double slope = make_direction(beta);
  if (!(slope < 0.0) && beta != 0.0) {
    linalg::for_each_index(m, [&](std::size_t i) { direction[i] = 0.0; });
    slope = make_direction(0.0);
  }
  if (capped) slope = keep_released_sides(shift);
  bool plain = false;
  if (!(slope < 0.0)) {
    // The plain projected gradient step always descends.
    trial = x - c * gradient;
    project(trial, trial);
    direction = trial - x;
    slope = dot(gradient, direction);
    plain = true;
  }
  if (!(slope < 0.0)) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format(
        "the conjugate direction is no descent direction at iteration {} (residual {:.3g}): rounding limits "
        "the accuracy; loosen the tolerance",
        iteration, residual);
    return false;
  }
  apply(stiffness, direction, s_direction);
  ++result.operator_applications;
  // Energy changes, not energies: near the solution the change is far
  // below the rounding of the energy itself. Non-monotone as SPG's: the
  // change is measured against the largest of the last kMemory energies;
  // monotone with a cap (non-monotone steps cycled there: a rough sweep
  // alternated between two held sets for 20000 iterations).
  const double allowance = capped ? 0.0 : *std::max_element(recent.begin(), recent.end()) - energy;
  const std::array<double, 2> along = linalg::sums<2>(m, [&](std::size_t i) {
    return std::array<double, 2>{direction[i] * sx[i], direction[i] * s_direction[i]};
  });
  const double linear = along[0];
  const double quadratic = 0.5 * along[1];
  double step = plain || !(quadratic > 0.0) ? 1.0 : -0.5 * slope / quadratic;
  double change = 0.0;
  bool clipped = false;
  int backtracks = 0;
  const AdhesionLaw& law = options.law;
  for (;; ++backtracks) {
    // The trial point, whether the wall clips it, and (if not) the
    // interaction energy's change, in one pass.
    const std::array<double, 2> moved = linalg::sums<2>(m, [&](std::size_t i) {
      trial[i] = x[i] + step * direction[i];
      const double cut = (below[i] ? trial[i] > lower[i] : trial[i] < lower[i]) ? 1.0 : 0.0;
      if (!physical[i]) return std::array<double, 2>{cut, 0.0};
      const double g = offset[i] + x[i];
      const double change_i = cell_energy(law, g + step * direction[i]) - cell_energy(law, g);
      return std::array<double, 2>{cut, change_i};
    });
    clipped = moved[0] > 0.0;
    double decrease = step * slope;
    if (clipped) {
      project(trial, trial);
      apply(stiffness, trial, scaled);  // S of the trial point
      ++result.operator_applications;
      // 1/2 t.S t - 1/2 x.S x = 1/2 (t - x).(S t + S x), and the
      // interaction energy's change.
      const std::array<double, 3> sums3 = linalg::sums<3>(m, [&](std::size_t i) {
        const double s_i = trial[i] - x[i];
        const double g = offset[i] + x[i];
        const double change_i = physical[i] ? cell_energy(law, offset[i] + trial[i]) - cell_energy(law, g) : 0.0;
        return std::array<double, 3>{0.5 * s_i * (scaled[i] + sx[i]), gradient[i] * s_i, change_i};
      });
      change = sums3[0] + sums3[2];
      decrease = sums3[1];
    } else {
      change = step * linear + step * step * quadratic + moved[1];
    }
    if (change <= allowance + kSufficientDecrease * decrease || backtracks >= kMaxBacktracks) break;
    step *= 0.5;
  }
  const double trial_energy = energy + change;
  if (backtracks >= kMaxBacktracks) {
    result.status = SolveStatus::breakdown;
    result.message =
        fmt::format("the line search found no decrease at iteration {} (residual {:.3g})", iteration, residual);
    return false;
  }
  const bool refresh = !clipped && (iteration + 1) % kRefreshEvery == 0;
  if (refresh) {
    x = trial;
    apply(stiffness, x, sx);
    ++result.operator_applications;
  }
  // Accept: the last gradient kept, v and S v updated, the new gradient
  // and the sums of the mean constraint's multiplier, in one pass.
  const std::array<double, 2> free_part = linalg::sums<2>(m, [&](std::size_t i) {
    old_gradient[i] = gradient[i];
    x[i] = trial[i];
    if (clipped) {
      sx[i] = scaled[i];
    } else if (!refresh) {
      sx[i] += step * s_direction[i];
    }
    gradient[i] = physical[i] ? sx[i] - cell_traction(law, offset[i] + x[i]) : sx[i];
    return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
  });
  free_shift = padded || !(free_part[1] > 0.0) ? 0.0 : free_part[0] / free_part[1];
  settle(free_shift);
  energy = trial_energy;
  recent[static_cast<std::size_t>(iteration + 1) % kMemory] = energy;
  restart = clipped || plain;
  return true;
}

bool AdhesiveContactSolver::Impl::spectral_gradient_step(Walk& walk, int iteration, double residual) {
  SolveResult& result = walk.result;
  double& energy = walk.energy;
  std::array<double, kMemory>& recent = walk.recent;
  double& alpha = walk.alpha;
  const std::size_t m = size();
  const double c = compliance;
  const double alpha_min = 1e-10 * c;
  const double alpha_max = 1e6 * c;
  // The spectral step and the line search along d = P(v - alpha G) - v.
  trial = x - alpha * gradient;
  project(trial, trial);
  direction = trial - x;
  const double slope = dot(gradient, direction);
  apply(stiffness, direction, s_direction);
  ++result.operator_applications;
  if (!(slope < 0.0)) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format(
        "the projected gradient step is no descent direction at iteration {} (residual {:.3g}): rounding limits "
        "the accuracy; loosen the tolerance",
        iteration, residual);
    return false;
  }
  const double elastic = 0.5 * dot(x, sx);
  const double linear = dot(direction, sx);
  const double quadratic = 0.5 * dot(direction, s_direction);
  const double reference = *std::max_element(recent.begin(), recent.end());
  double step = 1.0;
  double trial_energy = 0.0;
  int backtracks = 0;
  for (;; ++backtracks) {
    trial_energy = elastic + step * linear + step * step * quadratic + interaction_energy(x, &direction, step);
    if (trial_energy <= reference + kSufficientDecrease * step * slope || backtracks >= kMaxBacktracks) break;
    // Safeguarded quadratic interpolation of the energy along the line.
    const double curvature = trial_energy - energy - step * slope;
    double next = curvature > 0.0 ? -0.5 * slope * step * step / curvature : 0.5 * step;
    step = std::clamp(next, 0.1 * step, 0.5 * step);
  }
  if (backtracks >= kMaxBacktracks) {
    result.status = SolveStatus::breakdown;
    result.message =
        fmt::format("the line search found no decrease at iteration {} (residual {:.3g})", iteration, residual);
    return false;
  }
  // s = step d, y = G_new - G; the Barzilai-Borwein step s.s / s.y.
  if (step == 1.0) {
    x = trial;
  } else {
    x += step * direction;
  }
  if ((iteration + 1) % kRefreshEvery == 0) {
    apply(stiffness, x, sx);
    ++result.operator_applications;
  } else {
    sx += step * s_direction;
  }
  trial = gradient;  // the old gradient
  make_gradient();
  const double ss = step * step * dot(direction, direction);
  const double sy = step * linalg::sum(m, [&](std::size_t i) { return direction[i] * (gradient[i] - trial[i]); });
  alpha = sy > 0.0 ? std::clamp(ss / sy, alpha_min, alpha_max) : alpha_max;
  energy = trial_energy;
  recent[static_cast<std::size_t>(iteration + 1) % kMemory] = energy;
  return true;
}

void AdhesiveContactSolver::Impl::fill_result(SolveResult& result, std::span<const double> initial_gap,
                                              double approach) {
  const std::size_t n = grid.size();
  // A cell the projected step puts on the wall (the kink) is on it: within
  // the residual of it, it carries S v, not the law's traction at a gap of
  // rounding size (a start from the pressure K p lands cells 1e-13 m off
  // the wall, which would report -sigma0 on them). Periodic: the shift is
  // the projection's.
  {
    const double c = compliance;
    const auto y = [&](std::size_t i) { return x[i] - c * gradient[i]; };
    const std::optional<double> tau = projection_shift(y);
    if (tau) {
      linalg::for_each_index(size(), [&](std::size_t i) {
        if (physical[i] && x[i] != lower[i] && onto_side(i, y(i) - *tau) == lower[i]) x[i] = lower[i];
      });
    }
  }
  // The periodic mean pressure: the multiplier of mean v = 0, -G on the
  // cells off the wall (where the gradient vanishes at the solution).
  double mean_pressure_shift = 0.0;
  if (!padded) {
    const std::array<double, 2> free_part = linalg::sums<2>(n, [&](std::size_t i) {
      return off_wall(i) ? std::array<double, 2>{gradient[i], 1.0} : std::array<double, 2>{0.0, 0.0};
    });
    if (free_part[1] > 0.0) mean_pressure_shift = -free_part[0] / free_part[1];
  }
  result.approach = approach;
  result.pressure.resize(static_cast<Eigen::Index>(n));
  result.displacement.resize(static_cast<Eigen::Index>(n));
  result.gap.resize(static_cast<Eigen::Index>(n));
  const AdhesionLaw& law = options.law;
  double force = 0.0;
  double adhesive = 0.0;
  double max_pressure = -std::numeric_limits<double>::infinity();
  std::size_t at_wall = 0;
  std::size_t repulsive = 0;
  std::size_t interacting = 0;
  std::size_t plastic = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = index(k);
    // With a cap: on the kink (gap 0), or below it (plastic, gap < 0).
    const bool wall = x[i] <= lower[i];
    const bool kink = capped ? x[i] == lower[i] : wall;
    const double g =
        kink ? 0.0 : (capped ? initial_gap[k] + x[i] - approach : std::max(initial_gap[k] + x[i] - approach, 0.0));
    // Off the wall the law gives the pressure exactly; S v there differs
    // from it by the residual, which would show as spurious contact. On it,
    // S v may exceed a cap by the residual: the cap holds exactly.
    const double p = kink ? std::min(sx[i] + mean_pressure_shift, hardness) : cell_traction(law, g);
    result.pressure[static_cast<Eigen::Index>(k)] = p;
    result.displacement[static_cast<Eigen::Index>(k)] = x[i];
    result.gap[static_cast<Eigen::Index>(k)] = g;
    force += p;
    adhesive += std::min(p, 0.0);
    max_pressure = std::max(max_pressure, p);
    at_wall += wall ? 1 : 0;
    repulsive += wall && p > 0.0 ? 1 : 0;
    interacting += law.interacts(std::max(g, 0.0)) ? 1 : 0;
    plastic += capped && p >= hardness ? 1 : 0;
  }
  const double cells = static_cast<double>(n);
  result.total_force = force * grid.cell_area();
  result.mean_pressure = result.total_force / grid.domain_area();
  result.max_pressure = max_pressure;
  result.contact_fraction = static_cast<double>(at_wall) / cells;
  result.hardness = options.hardness;
  result.plastic_fraction = static_cast<double>(plastic) / cells;
  AdhesionRecord& record = result.adhesion;
  record.law = std::string(to_string(law.type));
  record.work = law.work;
  record.range = law.range;
  record.stress = law.stress();
  record.adhesive_force = adhesive * grid.cell_area();
  record.interaction_fraction = static_cast<double>(interacting) / cells;
  record.repulsive_contact_fraction = static_cast<double>(repulsive) / cells;
  // A result is finite, or it is no answer.
  if (!(std::isfinite(result.total_force) && std::isfinite(max_pressure) && std::isfinite(record.adhesive_force))) {
    result.status = SolveStatus::breakdown;
    result.message = fmt::format("the result is not finite (total force {:g}, largest pressure {:g} Pa)",
                                 result.total_force, max_pressure);
  }
  const double zone = law.cohesive_zone_length(e_star);
  if (at_wall > 0 && at_wall < n && zone < kUnderresolvedZone * cell_length(grid)) {
    result.warnings.push_back(fmt::format(
        "the cohesive zone pi E* w / (4 sigma0^2) = {:.3g} m is {:.3g} of the cell length {:.3g} m: the contact edge "
        "is not resolved, so the result depends on the grid (refine it to at least {:.3g} m cells)",
        zone, zone / cell_length(grid), cell_length(grid), zone / kUnderresolvedZone));
  }
}

// Load control: the approach whose displacement-controlled equilibrium
// carries `target`. F(delta) is not one function: the contact edge of a
// cohesive law is trapped by the grid (a cell snaps in or out of contact at
// a finite jump of the force), so the state at an approach depends on the
// path to it, and a loaded state and an unloaded one at the same approach
// differ. The search therefore follows one path: every trial solve starts
// from the `base`, the last state on the side of the target the search
// came from, moving the approach one way (towards more force when the
// force is too small, less when too large). It expands its steps (secant
// steps where the force grows with the approach, doubling ones otherwise)
// until the target is bracketed, then closes the bracket by secant steps
// safeguarded by bisection (the base following the near side). A bracket
// closing on a jump (the target between the force before and after a
// snap) is left from its other end, along that branch in the other
// direction (after a snap-in the contact is larger, and unloading it
// reaches the target: the state load control snaps to). Unloading past the
// force minimum detaches the surfaces (the force rises again): then the
// target is beyond the pull-off force of the branch, which is reported.
// The force tolerance is the requested relative one or the force the inner
// solve's residual leaves undetermined, whichever is larger.
SolveResult AdhesiveContactSolver::Impl::solve_force(std::span<const double> initial_gap, double target,
                                                     std::span<const double> initial_pressure) {
  const auto started = std::chrono::steady_clock::now();
  double mean_gap = 0.0;
  double min_gap = std::numeric_limits<double>::infinity();
  for (const double g : initial_gap) {
    mean_gap += g;
    min_gap = std::min(min_gap, g);
  }
  mean_gap /= static_cast<double>(initial_gap.size());
  // Periodic grids: the approach stays below the mean gap (infinite force there).
  const double ceiling = padded ? std::numeric_limits<double>::infinity() : mean_gap - 1e-9 * (mean_gap - min_gap);
  double approach = have_last && initial_pressure.empty() ? last_approach : std::min(min_gap, ceiling);
  SolveResult result =
      solve_displacement(initial_gap, approach, initial_pressure, have_last && initial_pressure.empty());
  int iterations = result.iterations;
  int products = result.operator_applications;
  const double probe = options.law.range;
  // The force the inner solve leaves undetermined: its residual bounds
  // each active cell's pressure error by tolerance times the largest
  // pressure.
  const auto tolerance = [&](const SolveResult& r) {
    const double scale = std::max(
        {std::abs(target), std::abs(r.adhesion.adhesive_force), std::abs(r.total_force - r.adhesion.adhesive_force)});
    double largest = 0.0;
    for (const double p : r.pressure) largest = std::max(largest, std::abs(p));
    const double active = std::max(r.adhesion.interaction_fraction, r.contact_fraction) * grid.domain_area();
    return std::max(options.force_tolerance * scale, options.tolerance * largest * active);
  };
  // The two ends of the bracket: approaches with the force below and above
  // the target, and their displacements.
  struct End {
    bool set = false;
    double approach = 0.0;
    double force = 0.0;
  };
  End low;
  End high;
  saved_low.resize(static_cast<Eigen::Index>(size()));
  saved_high.resize(static_cast<Eigen::Index>(size()));
  const auto keep = [&](End& end, Eigen::ArrayXd& saved) {
    end = {true, approach, result.total_force};
    saved = x;
  };
  bool loading = true;  // the base is `low` (the search raises the approach) or `high`
  double step_size = probe;
  double least_force = std::numeric_limits<double>::infinity();  // the least force solved, and where
  double least_at = approach;
  bool base_in_contact = false;
  int reversals = 0;  // brackets closed on a jump and left from their other end
  double least_slope = std::numeric_limits<double>::infinity();  // |dF / d delta| across the bracket
  int streak = 0;                     // the Illinois modification: how often the same end moved
  bool previous_slope_valid = false;  // the expansion's last base state, for its secant
  double previous_approach = 0.0;
  double previous_force = 0.0;
  constexpr int kMaxReversals = 3;
  std::string failure;
  int step = 0;
  for (; step < options.max_load_steps; ++step) {
    if (!result.converged()) {
      failure =
          fmt::format("the displacement-controlled solve at approach {:.6g} m failed: {}", approach, result.message);
      break;
    }
    const double force = result.total_force;
    if (std::abs(force - target) <= tolerance(result)) break;
    if (step == 0) loading = force < target;
    End& base = loading ? low : high;
    Eigen::ArrayXd& saved_base = loading ? saved_low : saved_high;
    End& far = loading ? high : low;
    Eigen::ArrayXd& saved_far = loading ? saved_high : saved_low;
    // File the state just solved.
    const bool on_base_side = loading ? force < target : force > target;
    if (!loading && on_base_side && base.set && base_in_contact && result.contact_fraction == 0.0) {
      // Unloading, and the surfaces came apart: the force minimum (the
      // pull-off) lies between the base and this approach. Back towards the
      // base with half the step; where the step vanishes, the target is
      // beyond the pull-off force.
      const double half = 0.5 * (approach - base.approach);
      step_size = std::abs(half);
      if (step_size <= 1e-2 * probe) {
        failure = fmt::format(
            "the force {:.6g} is beyond the pull-off force of this branch: unloading reached no less than {:.6g} "
            "(at approach {:.6g} m) before the surfaces came apart; load control has no equilibrium there: use "
            "displacement control (an approach sweep)",
            target, least_force, least_at);
        break;
      }
      if ((loading ? low : high).set) x = loading ? saved_low : saved_high;
      approach = base.approach + half;
      result = solve_displacement(initial_gap, approach, {}, true);
      iterations += result.iterations;
      products += result.operator_applications;
      continue;
    }
    if (!on_base_side) {
      keep(far, saved_far);
    } else {
      keep(base, saved_base);
      base_in_contact = result.contact_fraction > 0.0;
    }
    // +k: the low end moved k times in a row, -k: the high end.
    streak = force < target ? (streak > 0 ? streak + 1 : 1) : (streak < 0 ? streak - 1 : -1);
    if (force < least_force) {
      least_force = force;
      least_at = approach;
    }
    const double direction = loading ? 1.0 : -1.0;
    double next = 0.0;
    if (!far.set) {
      // Expanding: a secant step from the last two base states where the
      // force changes the right way, else doubling steps.
      next = base.approach + direction * step_size;
      if (previous_slope_valid && base.approach != previous_approach) {
        const double slope = (base.force - previous_force) / (base.approach - previous_approach);
        if (slope > 0.0 && std::isfinite(slope)) {
          const double secant = (target - base.force) / slope;
          next = base.approach + std::clamp(secant, -4.0 * step_size, 4.0 * step_size);
        }
      }
      step_size = std::abs(next - base.approach) * 2.0;
      previous_slope_valid = true;
      previous_approach = base.approach;
      previous_force = base.force;
    } else {
      const double width = std::abs(high.approach - low.approach);
      // A jump: the bracket is narrow against the law's range and its
      // force difference has stopped shrinking with it (the mean slope
      // across it 100 times the least seen in this bracket; on a steep but
      // continuous stretch of a rough contact it stays put), or the
      // bracket is at rounding.
      const double slope_across = std::abs(high.force - low.force) / width;
      least_slope = std::min(least_slope, slope_across);
      const bool narrow = width <= 1e-4 * probe && slope_across >= 100.0 * least_slope;
      if (narrow || width <= 1e-13 * std::max(std::abs(approach), probe)) {
        // Closed on a jump: leave the bracket from its other end, along
        // that end's branch the other way.
        if (++reversals > kMaxReversals) {
          failure = fmt::format(
              "the force jumps from {:.6g} to {:.6g} at approach {:.6g} m (cells snapping into or out of contact on "
              "this grid) and the target {:.6g} lies in the jump on every branch followed ({} reversals)",
              low.force, high.force, approach, target, kMaxReversals);
          break;
        }
        loading = !loading;
        (loading ? high : low).set = false;
        least_slope = std::numeric_limits<double>::infinity();
        previous_slope_valid = false;
        step_size = probe;
        streak = 0;
        next = (loading ? low : high).approach + (loading ? 1.0 : -1.0) * step_size;
      } else {
        // Regula falsi inside the bracket with the Illinois modification
        // (the retained end's residual halved while the other end moves,
        // Dowell & Jarratt 1971, BIT 11, 168), bisection where it leaves
        // the bracket's interior.
        const double weight = std::ldexp(1.0, -std::min(60, std::max(0, std::abs(streak) - 1)));
        const double f_low = (low.force - target) * (streak < 0 ? weight : 1.0);
        const double f_high = (high.force - target) * (streak > 0 ? weight : 1.0);
        next = low.approach - f_low * (high.approach - low.approach) / (f_high - f_low);
        const double lo = std::min(low.approach, high.approach);
        const double hi = std::max(low.approach, high.approach);
        if (!(next > lo + 1e-3 * width && next < hi - 1e-3 * width)) next = 0.5 * (low.approach + high.approach);
      }
    }
    // Every trial starts from the base (the path the search follows).
    if ((loading ? low : high).set) x = loading ? saved_low : saved_high;
    approach = std::min(next, ceiling);
    result = solve_displacement(initial_gap, approach, {}, true);
    iterations += result.iterations;
    products += result.operator_applications;
  }
  if (failure.empty() && step >= options.max_load_steps) {
    // breakdown, not iteration_limit: the last inner solve converged, and
    // the reason (the force missed) is the message, which front ends show
    // for a breakdown.
    result.status = SolveStatus::breakdown;
    failure = fmt::format(
        "the force {:.6g} was not reached in {} approach steps (last: {:.6g} at approach {:.6g} m{})", target,
        options.max_load_steps, result.total_force, approach,
        low.set && high.set ? fmt::format("; bracket [{:.6g}, {:.6g}] m", low.approach, high.approach) : std::string());
  }
  if (!failure.empty()) {
    if (result.converged()) result.status = SolveStatus::breakdown;
    result.message = failure;
  }
  result.iterations = iterations;
  result.operator_applications = products;
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

AdhesiveContactSolver::AdhesiveContactSolver(const Grid& grid, double e_star, AdhesiveSolverOptions options) {
  options.validate();
  impl_ = std::make_unique<Impl>(grid, e_star, std::move(options));
}

AdhesiveContactSolver::~AdhesiveContactSolver() = default;

std::string_view AdhesiveContactSolver::name() const {
  return impl_->options.precondition ? "adhesive-pcg" : "adhesive-spg";
}

const AdhesiveSolverOptions& AdhesiveContactSolver::options() const {
  return impl_->options;
}

SolveResult AdhesiveContactSolver::solve(std::span<const double> initial_gap, const Loading& loading,
                                         std::span<const double> initial_pressure) {
  Impl& m = *impl_;
  const std::size_t n = m.grid.size();
  if (initial_gap.size() != n) {
    throw InputError(fmt::format("adhesive solve: the initial gap has {} entries, but the grid has {} cells",
                                 initial_gap.size(), n));
  }
  if (!initial_pressure.empty() && initial_pressure.size() != n) {
    throw InputError(fmt::format("adhesive solve: the initial pressure has {} entries, but the grid has {} cells",
                                 initial_pressure.size(), n));
  }
  if (!std::isfinite(loading.value)) {
    throw InputError(fmt::format("{} = {} is invalid: must be finite", to_string(loading.mode), loading.value));
  }
  InterfaceLaw{m.options.hardness}.check_load(m.grid, loading);
  if (loading.mode == ControlMode::approach) {
    return m.solve_displacement(initial_gap, loading.value, initial_pressure, false);
  }
  return m.solve_force(initial_gap, loading.target_force(m.grid.domain_area()), initial_pressure);
}

}  // namespace halfspace::solvers
