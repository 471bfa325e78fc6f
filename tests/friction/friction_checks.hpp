// Independent checks of a converged tangential step: the slip increment
// recomputed from the returned shear by a fresh product, then Coulomb's
// bound, stick (no slip) and slip (traction at mu p opposite the slip).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "halfspace/solvers/tangential_result.hpp"
#include "support/analytic_solutions.hpp"
#include "support/grid_fields.hpp"
#include "support/pk_solvers.hpp"

namespace halfspace::testing {

// The normal contact the sphere tests load tangentially: a sphere of
// `radius` pressed by `force` into a free n x n grid 2.4 Hertz radii wide,
// solved by pk-fourier (frictionless: similar bodies, Dundurs' beta = 0).
struct SphereContact {
  Grid grid;
  SolveResult contact;
};

inline SphereContact hertz_sphere_contact(const ElasticPair& pair, double force, double radius, std::size_t n) {
  const double h = 2.4 * hertz_point(force, radius, pair.composite_modulus()).radius / static_cast<double>(n);
  const Grid grid = Grid::plane(n, n, h, h, Boundary::free);
  const Eigen::ArrayXd gap0 = field_from(grid, [&](double x, double y) { return (x * x + y * y) / (2 * radius); });
  const auto normal =
      solvers::make_solver(grid, pair.composite_modulus(), test_options(solvers::SolverType::pk_fourier));
  return {grid, normal->solve({gap0.data(), grid.size()}, Loading::force(force))};
}

// slip_tolerance (m) bounds |ds| in stick cells; angle_tolerance the
// misalignment |q/|q| + ds/|ds|| of slipping cells whose slip exceeds 100
// times it. `fixed`, if given, is the step's fixed tangential displacement
// (x then y: the pressure's coupling displacement of a dissimilar pair).
inline void expect_coulomb_conditions(TangentialOperator& op, const Eigen::ArrayXd& pressure, double mu,
                                      const TangentialState& previous, const TangentialResult& result,
                                      double slip_tolerance, double angle_tolerance,
                                      const Eigen::ArrayXd* fixed_x = nullptr,
                                      const Eigen::ArrayXd* fixed_y = nullptr) {
  const std::size_t n = op.local_size();
  const TangentialState& s = result.state;
  Eigen::ArrayXd ux(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd uy(static_cast<Eigen::Index>(n));
  op.apply({s.shear_x.data(), n}, {s.shear_y.data(), n}, {ux.data(), n}, {uy.data(), n});
  if (fixed_x != nullptr) ux += *fixed_x;
  if (fixed_y != nullptr) uy += *fixed_y;
  const double dax = s.approach_x - previous.approach_x;
  const double day = s.approach_y - previous.approach_y;
  int bound_violations = 0;
  int stick_violations = 0;
  int slip_violations = 0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(n); ++i) {
    const double limit = mu * pressure[i];
    const double q = std::hypot(s.shear_x[i], s.shear_y[i]);
    if (q > limit * (1.0 + 1e-12)) ++bound_violations;
    if (!(pressure[i] > 0.0)) continue;
    const double dx = ux[i] - previous.displacement_x[i] - dax;
    const double dy = uy[i] - previous.displacement_y[i] - day;
    const double ds = std::hypot(dx, dy);
    if (result.stick[i] == 1.0) {
      if (ds > slip_tolerance) ++stick_violations;
    } else {
      if (q < limit * (1.0 - 1e-9)) ++slip_violations;
      if (ds > 100.0 * slip_tolerance &&
          std::hypot(s.shear_x[i] / q + dx / ds, s.shear_y[i] / q + dy / ds) > angle_tolerance)
        ++slip_violations;
    }
  }
  EXPECT_EQ(bound_violations, 0);
  EXPECT_EQ(stick_violations, 0);
  EXPECT_EQ(slip_violations, 0);
}

}  // namespace halfspace::testing
