// The tangential step's force restoration under force control
// (TangentialIteration::restore_force, src/solvers/tangential_iteration.hpp):
// after a conjugate-gradient step moved slipping cells along their circles
// and clipped others, the force the step lacks is given back by the stick
// cells alone. Slipping cells stay where they are, stick cells pushed over
// their discs are clipped onto them and the force they lose goes to the
// rest, the force is met to rounding and every traction stays in its disc.
// The exact projection onto the force and the discs, which this replaced
// whenever a stick cell went over, shifted every slipping cell as well:
// taken on every step, it moved thousands of them off their circles and
// back, and a free 256^2 coupled sphere step took 860-1080 iterations
// instead of about 100 on rounding-level changes of the normal force
// (docs/development-log.md, 2026-11-30).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "halfspace/elastic_pair.hpp"
#include "halfspace/grid.hpp"
#include "halfspace/operators/tangential_operator.hpp"
#include "solvers/tangential_iteration.hpp"

namespace halfspace {
namespace {

using solvers::tangential::Fields;
using solvers::tangential::Problem;
using solvers::tangential::TangentialIteration;

constexpr ElasticBody kSteel{2.1e11, 0.3};
constexpr double kRadius = 1e3;  // mu p (Pa), the same on every contact cell

// An 8 x 8 contact: the first row out of contact, then alternately slipping
// cells (on their circles, at spread angles) and stick cells at 0.3 mu p,
// and one stick cell at 0.99 mu p along x.
struct Contact {
  static constexpr std::size_t kCells = 64;
  static constexpr std::size_t kNearLimit = 9;
  Grid grid = Grid::plane(8, 8, 1e-6, 1e-6, Boundary::free);
  TangentialOperator op{grid, ElasticPair::similar(kSteel)};
  std::vector<double> radius = std::vector<double>(kCells, kRadius);
  std::vector<double> qx = std::vector<double>(kCells, 0.0);
  std::vector<double> qy = std::vector<double>(kCells, 0.0);
  std::vector<double> work = std::vector<double>(8 * kCells, 0.0);
  std::vector<std::uint8_t> kind = std::vector<std::uint8_t>(kCells, 0);
  std::vector<bool> slipping = std::vector<bool>(kCells, false);
  std::vector<std::size_t> contact;  // the cells with mu p > 0
  double stick_cells = 0.0;

  Contact() {
    for (std::size_t i = 0; i < kCells; ++i) {
      if (i < 8) {
        radius[i] = 0.0;
        continue;
      }
      contact.push_back(i);
      const double angle = 0.7 * static_cast<double>(i);
      if (i % 2 == 0) {
        slipping[i] = true;
        qx[i] = kRadius * std::cos(angle);
        qy[i] = kRadius * std::sin(angle);
      } else {
        stick_cells += 1.0;
        const double scale = i == kNearLimit ? 0.99 : 0.3;
        qx[i] = scale * kRadius * (i == kNearLimit ? 1.0 : std::cos(angle));
        qy[i] = i == kNearLimit ? 0.0 : scale * kRadius * std::sin(angle);
      }
    }
  }

  Fields fields() {
    double* w = work.data();
    return {qx.data(),      qy.data(),      w,
            w + kCells,     w + 2 * kCells, w + 3 * kCells,
            w + 4 * kCells, w + 5 * kCells, w + 6 * kCells,
            w + 7 * kCells, kind.data()};
  }

  std::pair<double, double> force() const {
    double x = 0.0;
    double y = 0.0;
    for (std::size_t i = 0; i < kCells; ++i) {
      x += qx[i];
      y += qy[i];
    }
    return {x, y};
  }
};

// Restores (missing_x, missing_y) more force (sum of q, Pa) and checks the
// rules; returns restore_force's answer.
bool restore_and_check(Contact& c, double missing_x, double missing_y, bool slipping_cells_kept) {
  const auto [held_x, held_y] = c.force();
  Problem problem;
  problem.radius = c.radius.data();
  problem.contact = c.contact;
  problem.force_controlled = true;
  problem.target_x = held_x + missing_x;
  problem.target_y = held_y + missing_y;
  problem.capacity = kRadius * 56.0;
  problem.contact_cells = 56.0;
  const std::vector<double> before_x = c.qx;
  const std::vector<double> before_y = c.qy;
  solvers::TangentialOptions options;
  TangentialResult result;
  TangentialIteration it(c.op, options, problem, result, c.fields());
  const bool changed = it.restore_force(held_x, held_y, c.stick_cells);
  const auto [force_x, force_y] = c.force();
  EXPECT_NEAR(force_x, problem.target_x, 1e-12 * problem.capacity);
  EXPECT_NEAR(force_y, problem.target_y, 1e-12 * problem.capacity);
  for (std::size_t i = 0; i < Contact::kCells; ++i) {
    EXPECT_LE(std::hypot(c.qx[i], c.qy[i]), c.radius[i] * (1.0 + 1e-14)) << "cell " << i;
    if (c.slipping[i] && slipping_cells_kept) {
      EXPECT_EQ(c.qx[i], before_x[i]) << "slipping cell " << i << " moved";
      EXPECT_EQ(c.qy[i], before_y[i]) << "slipping cell " << i << " moved";
    }
  }
  return changed;
}

TEST(ForceRestoration, StickCellsAloneGiveASmallRemainderAlike) {
  Contact c;
  const double shift = 1e-3 * kRadius;  // nobody reaches the limit
  EXPECT_FALSE(restore_and_check(c, shift * c.stick_cells, -0.5 * shift * c.stick_cells, true));
  // Every stick cell moved by the same shift.
  EXPECT_NEAR(c.qx[Contact::kNearLimit], 0.99 * kRadius + shift, 1e-12 * kRadius);
  EXPECT_NEAR(c.qy[Contact::kNearLimit], -0.5 * shift, 1e-12 * kRadius);
}

TEST(ForceRestoration, ACellPushedOverItsDiscIsClippedAndTheRestTakeWhatItLost) {
  Contact c;
  // A shift of 0.05 mu p along x pushes the cell at 0.99 mu p over its disc.
  const double shift = 0.05 * kRadius;
  EXPECT_TRUE(restore_and_check(c, shift * c.stick_cells, 0.0, true));
  EXPECT_NEAR(std::hypot(c.qx[Contact::kNearLimit], c.qy[Contact::kNearLimit]), kRadius, 1e-12 * kRadius);
  // The other stick cells took a little more than the uniform shift.
  const double moved = c.qx[11] - 0.3 * kRadius * std::cos(0.7 * 11.0);
  EXPECT_GT(moved, shift);
  EXPECT_LT(moved, shift * c.stick_cells / (c.stick_cells - 1.0) * (1.0 + 1e-12));
}

TEST(ForceRestoration, MoreThanTheStickCellsCanHoldIsProjectedExactly) {
  Contact c;
  // Nearly all the remaining capacity along x: the stick cells alone cannot
  // give it, so the exact projection moves the slipping cells too; the
  // force is still met and every traction admissible.
  const double free_capacity = 56.0 * kRadius - c.force().first;
  EXPECT_TRUE(restore_and_check(c, 0.9 * free_capacity, 0.0, false));
}

}  // namespace
}  // namespace halfspace
