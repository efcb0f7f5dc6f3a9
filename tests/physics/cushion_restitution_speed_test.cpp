// Tests of the speed-dependent restitution: the law itself, its checks, and how every solver of
// the cushion impact applies it (the exact and paper solvers at the ball's normal speed; the
// default path, whose table holds outcomes per unit speed, hands every impact to the exact solver).
#include "physics/cushion_restitution_speed.h"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/cushion_exact_solver.h"
#include "physics/cushion_paper_solver.h"
#include "physics/cushion_rolling_surface.h"
#include "physics/cushion_tabulated_solver.h"
#include "tests/physics/cushion_test_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;

constexpr RestitutionSpeedDependence kLaw{2.0, 0.5};

CushionParams withLaw(const RestitutionSpeedDependence& law) {
  CushionParams p;  // the paper's snooker cushion
  p.restitution_speed_dependence = law;
  return p;
}

BallVelocity rolling(const CushionParams& p, double speed_mps, double angle_deg) {
  return incomingBall(speed_mps, degrees(angle_deg), speed_mps / p.radius_m, 0);
}

TEST(RestitutionSpeedDependence, IsConstantUpToTheKneeAndFallsAsAPowerAbove) {
  EXPECT_EQ(restitutionAtSpeed(0.9, kLaw, 0.5, 1e-6), 0.9);
  EXPECT_EQ(restitutionAtSpeed(0.9, kLaw, 2.0, 1e-6), 0.9);  // continuous at the knee
  EXPECT_NEAR(restitutionAtSpeed(0.9, kLaw, 8.0, 1e-6), 0.9 * 0.5, 1e-15);  // (2/8)^0.5
  // The normal rebound speed e(v) v grows as v^(1 - p): never falls with the incoming speed.
  double previous = 0;
  for (double v = 0.5; v < 20; v *= 1.3) {
    const double rebound = restitutionAtSpeed(0.9, kLaw, v, 1e-6) * v;
    EXPECT_GT(rebound, previous) << v;
    previous = rebound;
  }
  // At p = 1 it stays at the knee's; the floor holds where the law would go below it.
  EXPECT_NEAR(restitutionAtSpeed(0.9, {2.0, 1.0}, 6.0, 1e-6) * 6.0, 0.9 * 2.0, 1e-15);
  EXPECT_EQ(restitutionAtSpeed(0.9, {1e-9, 1.0}, 900, 1e-6), 1e-6);
}

TEST(RestitutionSpeedDependence, RefusesValuesNamingTheKeyAndTheRange) {
  using test::expectValueRejected;
  expectValueRejected([] { validateRestitutionSpeedDependence({0, 0.5}); },
                      "restitution_speed_dependence.knee_speed_mps = 0");
  expectValueRejected([] { validateRestitutionSpeedDependence({2e3, 0.5}); }, "(0, 1000]");
  expectValueRejected([] { validateRestitutionSpeedDependence({NAN, 0.5}); }, "knee_speed_mps");
  expectValueRejected([] { validateRestitutionSpeedDependence({2, 1.5}); },
                      "restitution_speed_dependence.falloff_exponent = 1.5");
  expectValueRejected([] { validateRestitutionSpeedDependence({2, -0.1}); }, "[0, 1]");
  // Through the model's own check too.
  expectValueRejected([] { validateCushionParams(withLaw({-1, 0.5})); }, "knee_speed_mps = -1");
  validateCushionParams(withLaw(kLaw));
}

TEST(RestitutionSpeedDependence, OnlyAFallingRestitutionBreaksTheScaling) {
  EXPECT_TRUE(impactScalesWithSpeed(CushionParams{}));
  EXPECT_TRUE(impactScalesWithSpeed(withLaw({2.0, 0.0})));
  EXPECT_FALSE(impactScalesWithSpeed(withLaw(kLaw)));
}

// Each solver solves an impact as the same impact with the constant e_e the law gives at the
// ball's normal speed v_y (not its speed): to the bit.
TEST(RestitutionSpeedDependence, TheSolversUseTheRestitutionAtTheNormalSpeed) {
  const CushionParams p = withLaw(kLaw);
  const BallVelocity in = incomingBall(5.0, degrees(40), 60, -30);  // v_y = 3.21 m/s
  CushionParams constant;
  constant.restitution = restitutionAtSpeed(p.restitution, kLaw, in.v.y(), kMinRestitution);
  EXPECT_NEAR(constant.restitution, p.restitution * std::sqrt(2.0 / in.v.y()), 1e-15);
  const CushionImpactResult exact = solveCushionImpactExact(p, in);
  EXPECT_EQ(exact.after.v, solveCushionImpactExact(constant, in).after.v);
  EXPECT_EQ(exact.after.w, solveCushionImpactExact(constant, in).after.w);
  const CushionImpactResult paper = solveCushionImpactPaper(p, in);
  EXPECT_EQ(paper.after.v, solveCushionImpactPaper(constant, in).after.v);
  // Below the knee nothing changes.
  const BallVelocity slow = incomingBall(2.5, degrees(40), 60, -30);  // v_y = 1.61 m/s
  EXPECT_EQ(solveCushionImpactExact(p, slow).after.v,
            solveCushionImpactExact(CushionParams{}, slow).after.v);
}

// The default path's table holds outcomes per unit speed; with the law on it must not answer, and
// every impact, rolling ones included, gets the exact solver's result (at the path's tolerance) to
// the bit.
TEST(RestitutionSpeedDependence, TheDefaultPathGoesExactWhenTheRestitutionFalls) {
  const CushionParams p = withLaw(kLaw);
  for (double speed : {1.0, 3.0, 6.0}) {
    const BallVelocity in = rolling(p, speed, 60);
    const CushionImpactResult tabulated = solveCushionImpactTabulated(p, in);
    const CushionImpactResult exact = solveCushionImpactExact(p, in, tabulatedFallbackOptions());
    EXPECT_EQ(tabulated.after.v, exact.after.v) << speed;
    EXPECT_EQ(tabulated.after.w, exact.after.w) << speed;
    EXPECT_GT(tabulated.rhs_evaluations, 0) << speed;  // solved, not looked up
  }
  test::expectRejected([&] { rollingSurfaceFor(p); }, "must go to the exact solver");
  // Even when the table of the same constants was just used on this thread.
  CushionParams constant = p;
  constant.restitution_speed_dependence.reset();
  EXPECT_TRUE(solveCushionImpactTabulated(constant, rolling(p, 1, 60)).rhs_evaluations == 0);
  test::expectRejected([&] { rollingSurfaceFor(p); }, "must go to the exact solver");
}

// A law that never bites changes nothing, to the bit: a flat one (p = 0) keeps the table, and a
// knee above the impact keeps the exact solver's result.
TEST(RestitutionSpeedDependence, ALawThatNeverBitesChangesNothing) {
  const BallVelocity in = rolling(CushionParams{}, 1.2, 70);
  EXPECT_EQ(solveCushionImpactTabulated(withLaw({0.5, 0.0}), in).after.v,
            solveCushionImpactTabulated(CushionParams{}, in).after.v);
  EXPECT_EQ(solveCushionImpactExact(withLaw({1000, 1.0}), in).after.v,
            solveCushionImpactExact(CushionParams{}, in).after.v);
}

}  // namespace
}  // namespace baize::physics
