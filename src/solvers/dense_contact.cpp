// The contact problem as a non-dimensional dense LCP (units and the mixed LCP
// of load control are explained in the header), and the way back to a
// SolveResult in SI units.
#include "halfspace/solvers/dense_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "halfspace/error.hpp"
#include "halfspace/material.hpp"
#include "halfspace/operators/dense_influence_operator.hpp"
#include "halfspace/solvers/contact_conditions.hpp"
#include "halfspace/solvers/interface_law.hpp"

namespace halfspace::solvers {
namespace {

std::string memory_string(double bytes) {
  constexpr double kMiB = 1024.0 * 1024.0;
  constexpr double kGiB = 1024.0 * kMiB;
  return bytes < kGiB ? fmt::format("{:.0f} MiB", bytes / kMiB) : fmt::format("{:.1f} GiB", bytes / kGiB);
}

// The automatic pressure unit: the mean pressure under load control; under
// displacement control the pressure that would push the deepest cell in by
// its overlap on its own, or the one that closes the widest gap if nothing
// overlaps (then the solution is p = 0 and any unit will do).
double automatic_pressure_unit(const Grid& grid, double self_influence, std::span<const double> initial_gap,
                               const Loading& loading) {
  if (loading.load_controlled()) return loading.target_force(grid.domain_area()) / grid.domain_area();
  double overlap = 0.0;
  double widest = 0.0;
  for (double g : initial_gap) {
    overlap = std::max(overlap, loading.value - g);
    widest = std::max(widest, std::abs(g - loading.value));
  }
  if (overlap > 0.0) return overlap / self_influence;
  return widest > 0.0 ? widest / self_influence : 1.0;
}

// The solver's own matrix K as an InfluenceOperator, for the independent
// check of a result (check_contact_conditions), without a copy of K.
class MatrixView final : public InfluenceOperator {
 public:
  MatrixView(const Grid& grid, const Eigen::MatrixXd& matrix) : grid_(grid), matrix_(matrix) {}
  const Grid& grid() const override { return grid_; }
  void apply(std::span<const double> pressure, std::span<double> displacement) override {
    const auto n = static_cast<Eigen::Index>(pressure.size());
    Eigen::Map<Eigen::VectorXd>(displacement.data(), n).noalias() =
        matrix_ * Eigen::Map<const Eigen::VectorXd>(pressure.data(), n);
  }
  double self_influence() const override { return matrix_(0, 0); }

 private:
  const Grid& grid_;
  const Eigen::MatrixXd& matrix_;
};

// A load of H times the domain (to this relative rounding) puts every cell
// at the cap.
constexpr double kFullCapRounding = 1e-12;

// The LCP's solution when every cell is at the cap: z at its upper bound and
// the multiplier (the approach) at the largest M z + q, the smallest that
// leaves no cell open (w = M z + q - lambda <= 0 everywhere). The problem
// fixes no approach there (any larger one also holds), and an interior-point
// method stops with a few cells just short of the cap.
LcpSolution all_capped_solution(const LcpProblem& problem) {
  LcpSolution solution;
  solution.z = problem.upper_bound;
  const Eigen::VectorXd response = problem.matrix * solution.z + problem.offset;
  solution.multiplier = response.maxCoeff();
  solution.w = response.array() - solution.multiplier;
  solution.objective = solution.z.dot(solution.w);
  solution.status = LcpStatus::solved;
  return solution;
}

}  // namespace

void DenseContactOptions::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("tolerance = {} is invalid: allowed range is (0, 1)", format_number(tolerance)));
  }
  if (!(std::isfinite(units.length) && units.length >= 0.0)) {
    throw InputError(fmt::format("length unit = {} m is invalid: must be finite and >= 0 (0: automatic)",
                                 format_number(units.length)));
  }
  if (!(std::isfinite(units.pressure) && units.pressure >= 0.0)) {
    throw InputError(fmt::format("pressure unit = {} Pa is invalid: must be finite and >= 0 (0: automatic)",
                                 format_number(units.pressure)));
  }
}

void check_dense_grid(const Grid& grid, std::string_view solver) {
  const std::size_t n = grid.size();
  if (n <= kMaxDenseCells) return;
  const double bytes = static_cast<double>(sizeof(double)) * static_cast<double>(n) * static_cast<double>(n);
  throw InputError(fmt::format(
      "solver '{}' works on the dense influence matrix and is limited to {} cells, but grid {} has {} cells "
      "(the matrix alone would take {}): use an FFT-based solver instead (solver pk-multilevel, the default, or "
      "pk)",
      solver, kMaxDenseCells, grid.shape_string(), n, memory_string(bytes)));
}

ContactLcp make_contact_lcp(const Grid& grid, double e_star, const Eigen::MatrixXd& influence,
                            std::span<const double> initial_gap, const Loading& loading,
                            const DenseContactOptions& options, const InterfaceLaw& law) {
  const std::size_t n = grid.size();
  const auto size = static_cast<Eigen::Index>(n);
  checked_composite_modulus(e_star);
  options.validate();
  loading.validate();
  check_field_size("initial gap", initial_gap.size(), grid);
  if (influence.rows() != size || influence.cols() != size) {
    throw InputError(
        fmt::format("influence matrix is {} x {}, but the grid has {} cells", influence.rows(), influence.cols(), n));
  }
  for (double g : initial_gap) {
    if (!std::isfinite(g)) throw InputError("initial gap holds a non-finite value");
  }
  if (grid.periodic() && !loading.load_controlled()) {
    // As for Polonsky-Keer: with zero-mean displacements the mean gap is
    // mean(g0) - approach, which cannot be negative.
    double mean_gap = 0.0;
    for (double g : initial_gap) mean_gap += g;
    mean_gap /= static_cast<double>(n);
    check_periodic_approach(loading.value, mean_gap);
  }

  ContactLcp contact;
  if (options.nondimensionalise) {
    contact.length_unit = options.units.length > 0.0
                              ? options.units.length
                              : (grid.dimension() == 1 ? grid.dx() : std::sqrt(grid.dx() * grid.dy()));
    contact.pressure_unit = options.units.pressure > 0.0
                                ? options.units.pressure
                                : automatic_pressure_unit(grid, influence(0, 0), initial_gap, loading);
    contact.gap_unit = contact.pressure_unit * contact.length_unit / e_star;
  }
  const double gap_unit = contact.gap_unit;
  const double approach = loading.load_controlled() ? 0.0 : loading.value;

  LcpProblem& lcp = contact.lcp;
  lcp.matrix = influence * (contact.pressure_unit / gap_unit);
  lcp.offset.resize(size);
  for (Eigen::Index i = 0; i < size; ++i)
    lcp.offset[i] = (initial_gap[static_cast<std::size_t>(i)] - approach) / gap_unit;
  if (loading.load_controlled()) {
    lcp.equality_row = Eigen::VectorXd::Ones(size);
    lcp.equality_value = loading.target_force(grid.domain_area()) / (grid.cell_area() * contact.pressure_unit);
  }
  if (law.hardness) lcp.upper_bound = Eigen::VectorXd::Constant(size, *law.hardness / contact.pressure_unit);
  return contact;
}

double contact_residual(std::span<const double> initial_gap, const Eigen::ArrayXd& pressure,
                        const Eigen::ArrayXd& displacement, const Eigen::ArrayXd& gap, double uniform_response_range,
                        std::optional<double> hardness) {
  const auto cells = static_cast<double>(pressure.size());
  const auto [g0_min, g0_max] = std::minmax_element(initial_gap.begin(), initial_gap.end());
  const double pressure_mean = pressure.sum() / cells;
  const double gap_scale = (*g0_max - *g0_min) + std::max(displacement.maxCoeff() - displacement.minCoeff(),
                                                          pressure_mean * uniform_response_range);
  const double weighted_gap = hardness ? (pressure * gap.max(0.0)).sum() : (pressure * gap.abs()).sum();
  const double overlap =
      hardness ? (((*hardness - pressure) / *hardness) * (-gap).max(0.0)).sum() : (-gap).max(0.0).sum();
  const double numerator = (pressure_mean > 0.0 ? weighted_gap / pressure_mean : 0.0) + overlap;
  return numerator == 0.0 ? 0.0 : numerator / (cells * gap_scale);
}

DenseContactSolver::DenseContactSolver(std::string_view name, const Grid& grid, double e_star,
                                       DenseContactOptions options, const InterfaceLaw& law)
    : ContactSolver(grid, law),
      name_(name),
      grid_(grid),
      e_star_(checked_composite_modulus(e_star)),
      options_(std::move(options)) {
  options_.validate();
  check_dense_grid(grid_, name_);
  influence_ = assemble_influence_matrix(grid_, e_star_);
}

DenseContactSolver::DenseContactSolver(std::string_view name, const Grid& grid, double e_star,
                                       Eigen::MatrixXd influence, DenseContactOptions options, const InterfaceLaw& law)
    : ContactSolver(grid, law),
      name_(name),
      grid_(grid),
      e_star_(checked_composite_modulus(e_star)),
      influence_(std::move(influence)),
      options_(std::move(options)) {
  options_.validate();
  const auto n = static_cast<Eigen::Index>(grid_.size());
  if (influence_.rows() != n || influence_.cols() != n) {
    throw InputError(fmt::format("influence matrix is {} x {}, but grid {} has {} cells", influence_.rows(),
                                 influence_.cols(), grid_.shape_string(), n));
  }
}

SolveResult DenseContactSolver::do_solve(std::span<const double> initial_gap, const Loading& loading,
                                         std::span<const double> /*initial_pressure*/) {
  const auto start = std::chrono::steady_clock::now();
  const std::optional<double> hardness = interface_law().hardness;
  last_lcp_ = make_contact_lcp(grid_, e_star_, influence_, initial_gap, loading, options_, interface_law());
  const bool all_capped =
      hardness && loading.load_controlled() &&
      loading.target_force(grid_.domain_area()) >= *hardness * grid_.domain_area() * (1.0 - kFullCapRounding);
  last_solution_ = all_capped ? all_capped_solution(last_lcp_.lcp) : solve_lcp(last_lcp_.lcp);
  const LcpSolution& lcp = last_solution_;
  const auto n = static_cast<Eigen::Index>(grid_.size());

  SolveResult result;
  result.solver = name_;
  result.tolerance = options_.tolerance;
  result.iterations = lcp.iterations;
  // A cell is in contact when its pressure exceeds its gap (both O(1) in
  // internal units). Pivoting gives exact zeros, so this changes nothing for
  // Lemke; an interior-point iterate is positive in both, and this picks the
  // side of the complementarity each cell converged to.
  result.pressure.resize(n);
  // With a cap, the same at the upper bound: a cell is at the cap when its
  // distance to it is below its overlap -w.
  const bool capped = last_lcp_.lcp.has_upper_bound();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double z = lcp.z[i];
    result.pressure[i] = z > 0.0 && z > lcp.w[i] ? z * last_lcp_.pressure_unit : 0.0;
    if (capped && (all_capped || last_lcp_.lcp.upper_bound[i] - z < -lcp.w[i])) {
      result.pressure[i] = *hardness;
    }
  }
  result.approach = loading.load_controlled() ? lcp.multiplier * last_lcp_.gap_unit : loading.value;
  result.displacement = (influence_ * result.pressure.matrix()).array();
  result.operator_applications = 1;
  const Eigen::Map<const Eigen::ArrayXd> g0(initial_gap.data(), n);
  result.gap = g0 + result.displacement - result.approach;

  result.total_force = grid_.cell_area() * result.pressure.sum();
  result.mean_pressure = result.total_force / grid_.domain_area();
  result.max_pressure = result.pressure.maxCoeff();
  result.contact_fraction = static_cast<double>((result.pressure > 0.0).count()) / static_cast<double>(n);
  if (capped) {
    result.hardness = hardness;
    result.plastic_fraction = static_cast<double>((result.pressure >= *hardness).count()) / static_cast<double>(n);
  }
  const Eigen::VectorXd uniform_response = influence_.rowwise().sum();  // K 1
  result.residual = contact_residual(initial_gap, result.pressure, result.displacement, result.gap,
                                     uniform_response.maxCoeff() - uniform_response.minCoeff(), hardness);
  result.residual_history = {result.residual};

  switch (lcp.status) {
    case LcpStatus::solved:
      if (result.residual <= options_.tolerance) {
        result.status = SolveStatus::converged;
      } else {
        result.status = SolveStatus::breakdown;
        result.message = fmt::format(
            "{} ended at a solution of its LCP, but the contact residual {:.3e} exceeds the "
            "tolerance {:.3e}",
            name_, result.residual, options_.tolerance);
      }
      break;
    case LcpStatus::iteration_limit:
      result.status = SolveStatus::iteration_limit;
      result.message = lcp.message;
      break;
    case LcpStatus::ray_termination:
    case LcpStatus::failure:
      result.status = SolveStatus::breakdown;
      result.message = lcp.message;
      break;
  }
  if (result.status == SolveStatus::converged) {
    // "Converged" must mean the conditions hold, checked apart from the
    // contact residual (contact_conditions.hpp), as Polonsky-Keer does.
    MatrixView op(grid_, influence_);
    Eigen::ArrayXd scratch(n);
    const ContactConditionReport check =
        check_contact_conditions(op, initial_gap, loading, interface_law().bounds(), result,
                                 ContactConditionTolerances::for_solver_tolerance(options_.tolerance),
                                 {scratch.data(), static_cast<std::size_t>(n)});
    ++result.operator_applications;
    if (!check.holds) {
      result.status = SolveStatus::breakdown;
      result.message = fmt::format(
          "{} ended at a solution of its LCP with the contact residual {:.3e}, but the "
          "independent check failed: {}",
          name_, result.residual, check.violation);
    }
  }
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace halfspace::solvers
