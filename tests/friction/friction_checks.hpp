// Independent checks of a converged tangential step: the slip increment
// recomputed from the returned shear by a fresh product, then Coulomb's
// bound, stick (no slip) and slip (traction at mu p opposite the slip).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>

#include "halfspace/operators/tangential_operator.hpp"
#include "halfspace/solvers/tangential_result.hpp"

namespace halfspace::testing {

// slip_tolerance (m) bounds |ds| in stick cells; angle_tolerance the
// misalignment |q/|q| + ds/|ds|| of slipping cells whose slip exceeds 100
// times it.
inline void expect_coulomb_conditions(TangentialOperator& op, const Eigen::ArrayXd& pressure, double mu,
                                      const TangentialState& previous, const TangentialResult& result,
                                      double slip_tolerance, double angle_tolerance) {
  const std::size_t n = op.local_size();
  const TangentialState& s = result.state;
  Eigen::ArrayXd ux(static_cast<Eigen::Index>(n));
  Eigen::ArrayXd uy(static_cast<Eigen::Index>(n));
  op.apply({s.shear_x.data(), n}, {s.shear_y.data(), n}, {ux.data(), n}, {uy.data(), n});
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
