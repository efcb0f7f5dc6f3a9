// Tests of the default cushion path: a ball the table does not answer gets the exact solver's
// result to the bit, a rolling ball gets the table's answer within its promise.
#include "physics/cushion_tabulated_solver.h"

#include <gtest/gtest.h>

#include "physics/cushion_rolling_surface.h"
#include "tests/physics/cushion_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;

TEST(CushionTabulatedSolver, GivesTheExactResultWhereTheTableDoesNotAnswer) {
  const CushionParams p;  // the paper's snooker cushion
  ExactSolverOptions options;
  options.tolerance = 1e-10;
  const BallVelocity sliding = incomingBall(1.4, degrees(50), 10, -20);
  const CushionImpactResult exact = solveCushionImpactExact(p, sliding, options);
  const CushionImpactResult tabulated = solveCushionImpactTabulated(p, sliding, options);
  EXPECT_EQ(tabulated.after.v, exact.after.v);
  EXPECT_EQ(tabulated.after.w, exact.after.w);
  EXPECT_EQ(tabulated.rhs_evaluations, exact.rhs_evaluations);
  EXPECT_EQ(tabulated.contact_changes.size(), exact.contact_changes.size());
}

TEST(CushionTabulatedSolver, GivesTheTablesAnswerForARollingBall) {
  const CushionParams p;
  const double speed = 0.9;
  const BallVelocity in = incomingBall(speed, degrees(35), speed / p.radius_m, 0);
  const CushionImpactResult tabulated = solveCushionImpactTabulated(p, in);
  const std::optional<BallVelocity> table = rollingSurfaceFor(p).answer(in);
  ASSERT_TRUE(table.has_value());
  EXPECT_EQ(tabulated.after.v, table->v);
  EXPECT_EQ(tabulated.after.w, table->w);
  EXPECT_EQ(tabulated.rhs_evaluations, 0);
  ExactSolverOptions reference;
  reference.tolerance = 1e-14;
  EXPECT_LE(test::velocityDifference(tabulated.after,
                                     solveCushionImpactExact(p, in, reference).after, p.radius_m),
            kRollingTablePromise * speed);
  ExactSolverOptions bad;
  bad.tolerance = 1;
  EXPECT_THROW(solveCushionImpactTabulated(p, in, bad), std::invalid_argument);
}

}  // namespace
}  // namespace baize::physics
