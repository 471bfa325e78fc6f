// The loading's checks: the periodic approach's one check and wording, shared
// by every solver and sweep (issue 32: it printed 17 digits and named no
// option a front end could map).
#include "halfspace/solvers/loading.hpp"

#include <gtest/gtest.h>

#include <span>
#include <string>

#include "halfspace/error.hpp"
#include "halfspace/solvers/solver_factory.hpp"
#include "support/grid_fields.hpp"

namespace halfspace {
namespace {

TEST(LoadingTest, PeriodicApproachAtOrBeyondTheMeanGapNamesTheOptionWithSixDigits) {
  EXPECT_NO_THROW(solvers::check_periodic_approach(1e-7, 9.903926402016164e-07));
  for (const double approach : {9.903926402016164e-07, 1e-3}) {
    try {
      solvers::check_periodic_approach(approach, 9.903926402016164e-07);
      ADD_FAILURE() << "approach " << approach << " accepted";
    } catch (const OptionError& error) {
      EXPECT_EQ(error.option(), "approach");
      EXPECT_EQ(error.rule(),
                "is invalid for a periodic surface: it must be below the mean initial gap 9.90393e-07 m (full contact "
                "needs infinite pressure there)");
      EXPECT_EQ(std::string(error.what()), "approach = " + error.value() + " " + error.rule());
    }
  }
}

// Every solver words it through the same check: the option, six digits.
TEST(LoadingTest, EverySolverRefusesAPeriodicApproachBeyondTheMeanGapAlike) {
  const Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::periodic);
  const Eigen::ArrayXd gap =
      testing::field_from(grid, [](double x, double) { return 1e-8 * (1.0 + std::cos(x / 1e-6)); });
  for (const char* name : {"pk", "pk-fourier", "pk-multilevel", "lemke", "lcpquad"}) {
    solvers::SolverOptions options;
    options.type = solvers::parse_solver_type(name);
    const auto solver = solvers::make_solver(grid, 1e11, options);
    try {
      solver->solve(std::span<const double>(gap.data(), grid.size()), Loading::approach(3e-8));
      ADD_FAILURE() << name << " accepted the approach";
    } catch (const OptionError& error) {
      EXPECT_EQ(error.option(), "approach") << name;
      EXPECT_EQ(error.value(), "3e-08 m") << name;
      EXPECT_NE(error.rule().find("below the mean initial gap"), std::string::npos) << name << ": " << error.rule();
    }
  }
}

}  // namespace
}  // namespace halfspace
